#include "controller/camera_controller.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "config/derive_seed.hpp"
#include "config/enum_names.hpp"
#include "config/ticks.hpp"
#include "controller/csp_problem_builder.hpp"
#include "fmt/format.h"
#include "fmt/ranges.h"
#include "protocol/net_message.hpp"
#include "vision/fixate_zoom.hpp"
#include "vision/relevance.hpp"

namespace argus::controller {
namespace {

// The negotiator's stream is the node's own, apart from every other stream of the run.
constexpr std::uint64_t negotiation_stream = 0x64656d6f7465ULL;  // "demote"

bool better_bid(const protocol::relevance_bid& a, const protocol::relevance_bid& b) {
  if (a.relevance != b.relevance) return a.relevance > b.relevance;
  return a.bidder < b.bidder;
}

std::string_view name_of(vision::tracking_state s) {
  switch (s) {
    case vision::tracking_state::track:
      return "track";
    case vision::tracking_state::wait:
      return "wait";
    case vision::tracking_state::search:
      return "search";
    case vision::tracking_state::failed:
      return "failed";
  }
  return "track";
}

// What the child FSM takes of a look.
vision::track_observation observation_of(const look_result& r) {
  vision::track_observation obs;
  obs.found = r.found;
  obs.box = cv::Rect(r.box);
  obs.score = r.score;
  return obs;
}

vision::tracking_fsm_settings fsm_settings(const config::controller_settings& controller) {
  vision::tracking_fsm_settings t;
  if (!controller.zoom_in_track) t.fixate.zoom_gain = 0.0;
  return t;
}

}  // namespace

camera_controller::camera_controller(node_identity me, const config::scenario& scenario,
                                     bool collaborate)
    : me_(std::move(me)),
      collaborate_(collaborate),
      settings_(scenario.controller),
      tick_(scenario.run.tick),
      message_timeout_(scenario.network.message_timeout),
      fsm_(me_.limits, scenario.controller, fsm_settings(scenario.controller)),
      negotiator_(config::to_ticks(settings_.merge_timeout, tick_),
                  config::to_ticks(settings_.demotion_backoff_max, tick_),
                  config::derive_seed(scenario.run.seed,
                                      negotiation_stream ^ static_cast<std::uint64_t>(me_.id))),
      pose_(me_.home),
      bid_fsm_(me_.limits, scenario.controller, fsm_settings(scenario.controller)) {
  // nop
}

std::int64_t camera_controller::ticks(config::seconds d) const {
  return config::to_ticks_at_least_one(d, tick_);
}

node_state camera_controller::state() const noexcept {
  if (task_) return node_state::performing_task;
  if (!pending_.empty()) return node_state::computing_relevance;
  return node_state::idle;
}

std::optional<task_id> camera_controller::task() const {
  if (!task_) return std::nullopt;
  return task_->task;
}

std::vector<int> camera_controller::members() const {
  std::vector<int> out;
  for (const auto& [id, m] : members_) out.push_back(id);
  return out;
}

double camera_controller::decayed(double relevance, std::int64_t age) const {
  // Footnote 2: relevance decays without fresh evidence, to zero over the member failure
  // timeout.
  const double horizon = static_cast<double>(ticks(settings_.member_failure_timeout));
  return relevance * std::max(0.0, 1.0 - static_cast<double>(age) / horizon);
}

double camera_controller::relevance(std::int64_t now) const {
  if (!task_) return 0.0;
  return decayed(seen_relevance_, now - seen_tick_);  // since the last sighting
}

double camera_controller::relevance_of(const cv::Rect2d& box, bool busy) const {
  const auto required = vision::centring_pose(pose_, box, me_.frame);
  return vision::relevance(
      required, me_.limits, settings_,
      busy ? vision::camera_availability::busy : vision::camera_availability::free);
}

bool camera_controller::locked() const {
  return task_ && now_ < pinned_until_;
}

void camera_controller::send(int to, protocol::group_message m, controller_output& out) const {
  out.messages.push_back(outgoing_message{to, std::move(m)});
}

void camera_controller::emit(controller_output& out, events::event e) const {
  std::visit(
      [this](auto& x) {
        if constexpr (requires { x.camera; }) x.camera = me_.id;
      },
      e);
  out.events.push_back(logged(e));
}

frame_plan camera_controller::plan(std::int64_t, bool looking) {
  frame_plan p;
  p.wants_frame = looking && state() != node_state::idle;
  return p;
}

strategy_status camera_controller::status() const {
  return {state(), task(), role_, fsm_.state()};
}

controller_output camera_controller::step(const controller_input& in) {
  now_ = in.tick;
  pose_ = in.pose;
  controller_output out;
  take_looks(in, out);
  for (auto t : in.cancels) cancel(t, me_.id, out);
  for (const auto& q : in.queries) take_query(q, out);
  for (const auto& m : in.messages) take_message(m, out);
  run_timers(out);
  plan_next(out);
  if (state() != reported_state_) {
    emit(out, events::node_state{.from = std::string(name_of(reported_state_)),
                                 .to = std::string(name_of(state()))});
    reported_state_ = state();
  }
  return out;
}

// --- sensing ---------------------------------------------------------------------------------

void camera_controller::take_looks(const controller_input& in, controller_output& out) {
  seen_now_.reset();
  bid_seen_.reset();
  for (const auto& r : in.looks) {
    if (task_ && r.task == task_->task) {
      seen_now_ = r;
      if (r.model && settings_.share_model && role_ == group_role::leader) {
        // Her colours at the size this camera zoomed to: what its next queries carry.
        task_->target = *r.model;
        emit(out, events::signature_shared{.task = task_->task});
      }
      if (r.found) {
        seen_relevance_ = relevance_of(r.box, false);
        seen_tick_ = now_;
      }
    }
    for (auto& p : pending_) {
      if (p.task.task != r.task) continue;
      if (!p.bid_sent && !p.unconfirmed) {
        weigh_evidence(p, r, out);
      } else if (p.bid_sent && r.found) {
        // Followed after its bid (track_while_bidding): it joins with what it sees last.
        p.relevance = relevance_of(r.box, false);
        p.seen_tick = now_;
      }
    }
    if (bid_followed_ && r.task == *bid_followed_) bid_seen_ = r;
  }
}

void camera_controller::weigh_evidence(pending_query& p, const look_result& r,
                                       controller_output& out) {
  const auto window = config::to_ticks(settings_.bid_evidence_time, tick_);
  if (!p.first_found) {
    if (!r.found) return;
    p.first_found = now_;
    p.look_until = std::max(p.look_until, now_ + window + 1);  // the deciding frame is looked at
  }
  ++p.frames;
  if (r.found) {
    ++p.found;
    p.score_sum += r.score;
    // Fig. 11 / eq. (1): the bid is the relevance as if free; a busy bidder says so.
    p.relevance = relevance_of(r.box, false);
    p.seen_tick = now_;
  }
  if (now_ - *p.first_found < window) return;
  const double found_fraction = static_cast<double>(p.found) / p.frames;
  const double mean_score = p.score_sum / p.found;
  if (found_fraction < settings_.bid_min_found_fraction ||
      mean_score < settings_.bid_min_mean_score) {
    p.unconfirmed = true;
    p.look_until = now_;
    return;
  }
  if (p.relevance < settings_.min_relevance) {
    p.look_until = now_;  // below the minimum acceptable relevance: no bid
    return;
  }
  protocol::relevance_bid bid;
  bid.task = p.task.task;
  bid.leader = p.leader;
  bid.term = p.term;
  bid.auction = p.auction;
  bid.bidder = me_.id;
  bid.relevance = p.relevance;
  bid.busy = task_.has_value();
  bid.locked = locked();
  if (task_) {
    bid.other_task = task_->task;
    bid.other_leader = leader_;
  }
  send(p.querier, bid, out);
  p.bid_sent = true;
  p.bid_at = now_;
  emit(out, events::bid{.task = bid.task,
                        .leader = bid.leader,
                        .auction = bid.auction,
                        .relevance = bid.relevance,
                        .busy = bid.busy,
                        .found_fraction = found_fraction,
                        .mean_score = mean_score});
  // Section IV-B: a node that belongs to a group and is queried by another, or that is queried
  // by two groups, initiates conflict resolution.
  const protocol::conflict_claim claim{
      .task = bid.task, .leader = bid.leader, .term = bid.term, .relevance = bid.relevance};
  if (bid.locked) return;  // placed by a conflict's result: not to be moved yet
  if (task_) {
    report_conflict(
        {{.task = task_->task, .leader = leader_, .term = term_, .relevance = relevance(now_)},
         claim},
        out);
    return;
  }
  for (const auto& other : pending_) {
    if (&other == &p || !other.bid_sent || other.task.task == p.task.task) continue;
    report_conflict({{.task = other.task.task,
                      .leader = other.leader,
                      .term = other.term,
                      .relevance = other.relevance},
                     claim},
                    out);
    return;
  }
}

void camera_controller::take_query(const operator_query& q, controller_output& out) {
  if (task_ && task_->task == q.task.task) return;
  // Taken from a group by the operator, this node is claimed by two groups: it tells the
  // groups' conflict solver, so that the two groups decide between them which of their cameras
  // carries which task (Fig. 19).
  // A leader first gives its group to its best member, so that the task it leaves keeps a
  // leader (the member would otherwise wait out the leader failure timeout).
  if (task_ && role_ == group_role::leader && collaborate_) hand_over(-1.0, out, true);
  std::optional<protocol::conflict_claim> was;
  if (task_ && role_ == group_role::member && collaborate_)
    was = protocol::conflict_claim{
        .task = task_->task, .leader = leader_, .term = term_, .relevance = relevance(now_)};
  if (task_) leave_task("operator", out);
  pending_.clear();
  start_task(q.task, group_role::leader, me_.id, 0.0, now_, next_term(q.task.task), out);
  seen_relevance_ = relevance_of(q.box, false);
  emit(out, events::task_created{.task = q.task.task,
                                 .min_cameras = q.task.min_cameras,
                                 .max_cameras = q.task.max_cameras,
                                 .relevance = seen_relevance_,
                                 .term = term_});
  if (was)
    report_conflict({*was,
                     {.task = q.task.task,
                      .leader = me_.id,
                      .term = term_,
                      .relevance = std::min(1.0, std::max(0.0, seen_relevance_))}},
                    out);
}

// --- messages --------------------------------------------------------------------------------

void camera_controller::take_message(const received_message& m, controller_output& out) {
  std::visit(
      [&](const auto& msg) {
        using T = std::decay_t<decltype(msg)>;
        if constexpr (std::is_same_v<T, protocol::query_relevance>) {
          on_query(m.origin, msg, out);
        } else if constexpr (std::is_same_v<T, protocol::relevance_bid>) {
          on_bid(m.origin, msg, out);
        } else if constexpr (std::is_same_v<T, protocol::join>) {
          on_join(m.origin, msg, out);
        } else if constexpr (std::is_same_v<T, protocol::status>) {
          on_status(m.origin, msg, out);
        } else if constexpr (std::is_same_v<T, protocol::handover>) {
          on_handover(msg, out);
        } else if constexpr (std::is_same_v<T, protocol::demotion>) {
          on_demotion(msg, out);
        } else if constexpr (std::is_same_v<T, protocol::csp_conflict>) {
          on_csp_conflict(msg, out);
        } else if constexpr (std::is_same_v<T, protocol::csp_query>) {
          on_csp_query(m.origin, msg, out);
        } else if constexpr (std::is_same_v<T, protocol::csp_data>) {
          on_csp_data(msg, out);
        } else if constexpr (std::is_same_v<T, protocol::csp_result>) {
          on_csp_result(msg, out);
        } else if constexpr (std::is_same_v<T, protocol::task_cancel>) {
          cancel(msg.task, m.origin, out);
        }
      },
      m.message);
}

void camera_controller::on_query(int from, const protocol::query_relevance& q,
                                 controller_output& out) {
  const auto t = q.task.task;
  if (cancelled_.count(t) != 0) return;
  heard_term(t, q.term);
  if (q.relay) {
    // Section IV-A: a leader recruits through its members, who announce to their neighbours.
    if (task_ && task_->task == t && role_ == group_role::member && leader_ == q.leader &&
        q.term >= term_) {
      auto announce = q;
      announce.relay = false;
      send(protocol::broadcast, announce, out);
    }
    return;
  }
  if (task_ && task_->task == t) {
    if (role_ == group_role::leader && q.leader != me_.id)
      met_other_leader(q.leader, q.term, q.leader, out);
    return;
  }
  if (q.leader == me_.id) return;
  auto pending = std::find_if(pending_.begin(), pending_.end(),
                              [t](const pending_query& p) { return p.task.task == t; });
  if (pending != pending_.end()) {
    const bool new_auction = pending->leader != q.leader || pending->auction != q.auction;
    if (!pending->bid_sent) {
      pending->leader = q.leader;
      pending->term = q.term;
      pending->querier = from;
      pending->auction = q.auction;
      return;
    }
    // A bid already went to an earlier auction and no join came of it (not chosen, or the
    // join was lost): the leader is auctioning again, so this node bids again rather than
    // staying deaf to the task until its bidding timeout.
    if (!new_auction) return;
    pending_.erase(pending);
  }
  pending_query p;
  p.task = q.task;
  p.leader = q.leader;
  p.term = q.term;
  p.querier = from;
  p.auction = q.auction;
  p.look_until = now_ + ticks(settings_.relevance_look_time);
  p.give_up_at = now_ + ticks(settings_.bidding_timeout);
  pending_.push_back(std::move(p));
  emit(out, events::queried{.task = t, .leader = q.leader, .auction = q.auction, .from = from});
}

void camera_controller::on_bid(int from, const protocol::relevance_bid& b, controller_output& out) {
  if (!task_ || task_->task != b.task || b.leader != leader_) return;
  if (role_ == group_role::member) {
    // Members forward group messages to their leader: a bidder's own bid, never one another
    // member forwarded (two members each taking the other for its leader, in the moment a
    // demotion is on its way, would pass it back and forth for good).
    if (from == b.bidder) send(leader_, b, out);
    return;
  }
  if (!auction_ || b.auction != auction_->id) return;
  if (from != b.bidder) relayed_by_[b.bidder] = from;
  auto [it, fresh] = auction_->bids.emplace(b.bidder, b);
  if (!fresh && b.relevance > it->second.relevance) it->second = b;
}

void camera_controller::on_join(int from, const protocol::join& j, controller_output& out) {
  if (cancelled_.count(j.task.task) != 0) return;
  heard_term(j.task.task, j.term);
  if (j.invitee != me_.id) {
    // A copy for the member that relayed the invitee's bid, from the leader itself: pass it on.
    if (task_ && task_->task == j.task.task && role_ == group_role::member && leader_ == j.leader &&
        from == j.leader) {
      send(j.invitee, j, out);
      relayed_for_.insert(j.invitee);
    }
    return;
  }
  if (task_) {
    if (task_->task == j.task.task) return;
    if (!j.reassign) {
      emit(out,
           events::join_refused{.task = j.task.task, .leader = j.leader, .busy_with = task_->task});
      return;
    }
    leave_task("reassigned", out);
  }
  double r = 0.0;
  std::int64_t seen = now_;
  for (const auto& p : pending_) {
    if (p.task.task != j.task.task || !p.bid_sent) continue;
    r = p.relevance;
    seen = p.seen_tick;
  }
  pending_.clear();
  const bool followed = bid_followed_ == j.task.task;
  start_task(j.task, group_role::member, j.leader, r, seen, j.term, out);
  if (followed) fsm_ = bid_fsm_;  // in Track (or Wait) on her already
  emit(out, events::joined{
                .task = j.task.task, .leader = j.leader, .reassign = j.reassign, .term = j.term});
  send(protocol::broadcast, own_status(), out);
}

void camera_controller::on_status(int from, const protocol::status& s, controller_output& out) {
  // A node that missed the cancellation (lost messages, out of reach) hears it again.
  if (cancelled_.count(s.task) != 0) {
    send(s.sender, protocol::task_cancel{s.task, me_.id}, out);
    return;
  }
  heard_term(s.task, s.term);
  if (last_result_ && now_ < last_result_until_ && !s.leaving) retell_place(s, out);
  if (!task_ || s.task != task_->task || s.sender == me_.id) return;
  // Terms: a status of another leadership older than this node's is stale (the leader handed
  // over or was taken for failed, its statuses still in flight or echoed by nodes that have
  // not noticed); a leader answers it with its own, so that the sender learns the newer term.
  // A late copy of its own leader's status from before the leader's newer term is stale too.
  // Statuses of its own leadership's nodes may lag behind its term: they have not heard it yet.
  if (s.leader != leader_ && s.term < term_) {
    if (role_ == group_role::leader) answer_stale(s.sender, out);
    return;
  }
  if (s.sender == leader_ && s.term < term_) return;
  if (role_ == group_role::member && handed_over_at_) {
    // The hand-over is confirmed by the new leader's own status as leader: now leave.
    if (s.sender == leader_ && s.leader == leader_) leave_task("handed_over", out);
    return;
  }
  if (role_ == group_role::member) {
    // Members forward group messages between their leader and the cameras they recruited
    // through their own neighbourhood, which may be beyond the leader's hop limit.
    // A node that follows this node's leader without being on the leader's list may be out of
    // the leader's reach: one demoted on hearing this node's status, say. Relay for it too, or
    // it takes the leader it cannot hear for failed, leads, hears this node and is demoted
    // again, every leader failure timeout.
    if (s.leader == leader_ && s.sender != leader_ && !s.leaving && leader_members_ &&
        std::find(leader_members_->begin(), leader_members_->end(), s.sender) ==
            leader_members_->end())
      relayed_for_.insert(s.sender);
    // Only first-hand statuses are relayed, one hop of relay each way: two members that each
    // relay for the other would otherwise pass every status of the leader back and forth for
    // good, a new copy joining the circle each heartbeat (penn_station seed 6 with the
    // re-taken model grew to 24 GB at 690 s), and keep a failed leader alive on its echoes.
    const bool first_hand = from == s.sender;
    if (first_hand && s.leader == leader_ && relayed_for_.count(s.sender) != 0)
      send(leader_, s, out);
    if (s.sender != leader_) return;
    // Not back to the leader: a node this one relayed for may since have become its leader.
    if (first_hand)
      for (int far : relayed_for_)
        if (far != leader_) send(far, s, out);
    last_leader_status_ = now_;
    leader_members_ = s.members;
    if (s.leader != s.sender) {
      // Fig. 15's two leaders can each accept the other's demote (each sent its own only after
      // the other's arrived): then this node's leader follows this node. It leads, at a new
      // epoch: following itself, nobody would lead, and its old epoch has ended.
      if (s.leader == me_.id) {
        become_leader("leader_demoted", out);
        return;
      }
      follow_leader(s.leader, s.term, "leader_demoted", out);
      return;
    }
    term_ = s.term;  // its leader's newer epoch (a merge it won), or the same
    const bool listed = std::find(s.members.begin(), s.members.end(), me_.id) != s.members.end();
    if (!listed && now_ - joined_ > ticks(settings_.leader_failure_timeout))
      leave_task("dropped", out);
    return;
  }
  if (s.leader == me_.id && s.leaving) {
    if (members_.erase(s.sender) != 0)
      emit(out, events::member_change{
                    .task = s.task, .member = s.sender, .reason = "left", .added = false});
    return;
  }
  if (s.leader == me_.id) {
    auto [it, fresh] = members_.emplace(s.sender, member_record{s.relevance, now_, now_});
    if (!fresh) {
      it->second.relevance = s.relevance;
      it->second.last_status = now_;
    } else {
      // Section IV-A: "the leader node includes that node into its group".
      emit(out, events::member_change{
                    .task = s.task, .member = s.sender, .reason = "status", .added = true});
    }
    return;
  }
  met_other_leader(s.leader, s.term, s.sender, out);
}

void camera_controller::on_handover(const protocol::handover& h, controller_output& out) {
  heard_term(h.task.task, h.term);
  if (!task_ && h.new_leader == me_.id && cancelled_.count(h.task.task) == 0) {
    // Left the group while the hand-over was on its way: the task must not die with it.
    start_task(h.task, group_role::member, h.old_leader, 0.0, now_, h.term - 1, out);
    emit(out, events::joined{
                  .task = h.task.task, .leader = h.old_leader, .reassign = false, .term = term_});
  }
  // Terms: a hand-over no newer than the leadership followed is stale (an earlier one, late).
  // The new leader takes over whatever leadership it follows; the others only from the old
  // leader they follow.
  if (!task_ || role_ != group_role::member || task_->task != h.task.task || h.term <= term_ ||
      (leader_ != h.old_leader && h.new_leader != me_.id))
    return;
  if (h.new_leader != me_.id) {
    leader_ = h.new_leader;
    term_ = h.term;
    last_leader_status_ = now_;
    return;
  }
  // The hand-over's epoch is one past the old leader's; this node may know a newer one (a
  // leadership of its own that the old leader never heard of, during a partition, say): a new
  // leadership is past every epoch its node has heard, or it would take up an ended term.
  become_leader("handover", out, std::max(h.term, next_term(h.task.task)));
  for (int m : h.members)
    if (m != me_.id) members_[m] = member_record{0.0, now_, now_};
}

void camera_controller::on_demotion(const protocol::demotion& d, controller_output& out) {
  // A leader that missed the cancellation hears it again, and nothing else about the task.
  if (cancelled_.count(d.task) != 0) {
    if (d.step == protocol::demotion_step::demote)
      send(d.sender, protocol::task_cancel{d.task, me_.id}, out);
    return;
  }
  heard_term(d.task, d.term);
  if (!task_ || role_ != group_role::leader || d.task != task_->task) {
    // No longer a leader of that task: the negotiation is over for this side.
    if (d.step == protocol::demotion_step::demote)
      send(d.sender,
           protocol::demotion{.step = protocol::demotion_step::nack,
                              .task = d.task,
                              .sender = me_.id,
                              .term = task_ && task_->task == d.task ? term_ : 0,
                              .members = {}},
           out);
    return;
  }
  // Terms: Fig. 15 settles leaders of one term; an older leadership learns the newer one, a
  // newer one is followed.
  if (d.term < term_) {
    answer_stale(d.sender, out);
    return;
  }
  if (d.term > term_) {
    follow_leader(d.sender, d.term, "newer_term", out);
    return;
  }
  demotion_negotiator::actions a;
  negotiator_.receive(d.sender, d.step, now_, a);
  if (d.step == protocol::demotion_step::ack) {
    for (int m : d.members)
      if (m != me_.id) absorb(m, out);
    // Absorbing a demoted leader starts a new term: its members, who knew its term, now hear
    // a newer one.
    term_ = next_term(task_->task);
    heard_term(task_->task, term_);
    emit_leader_changed(me_.id, me_.id, "merged", out);
    send(protocol::broadcast, own_status(), out);
  }
  apply_demotions(a, out, d.term);
}

void camera_controller::apply_demotions(const demotion_negotiator::actions& a,
                                        controller_output& out,
                                        std::optional<protocol::term_epoch> peer_term) {
  for (const auto& [peer, step] : a.sends) {
    protocol::demotion d{
        .step = step, .task = task_->task, .sender = me_.id, .term = term_, .members = {}};
    if (step == protocol::demotion_step::ack) d.members = members();
    send(peer, d, out);
    emit(out, events::demotion_sent{
                  .task = d.task, .to = peer, .step = std::string(protocol::kind_of(d))});
  }
  for (int peer : a.absorbed) absorb(peer, out);
  if (a.demoted_to) follow_leader(*a.demoted_to, peer_term.value_or(term_), "demoted", out);
}

void camera_controller::cancel(task_id task, int from, controller_output& out) {
  if (!cancelled_.insert(task).second) return;
  emit(out, events::cancel_heard{.task = task, .from = from});
  std::erase_if(pending_, [&](const pending_query& p) { return p.task.task == task; });
  // Spread once: the group may reach beyond the operator's camera's hop limit.
  send(protocol::broadcast, protocol::task_cancel{task, me_.id}, out);
  if (task_ && task_->task == task) leave_task("cancelled", out);
}

// --- transitions -----------------------------------------------------------------------------

void camera_controller::start_task(const protocol::task_description& task, group_role role,
                                   int leader, double relevance, std::int64_t seen,
                                   protocol::term_epoch term, controller_output&) {
  task_ = task;
  role_ = role;
  leader_ = leader;
  term_ = term;
  heard_term(task.task, term);
  joined_ = now_;
  last_leader_status_ = now_;
  seen_relevance_ = relevance;
  seen_tick_ = seen;
  fsm_.reset();
  forget_group();
  last_bids_.clear();
  relayed_for_.clear();
  leader_members_.reset();
  relayed_by_.clear();
  handed_over_at_.reset();
  next_auction_at_ = now_;
  pinned_until_ = 0;
}

void camera_controller::forget_group() {
  members_.clear();
  auction_.reset();
  csp_.reset();
  csp_reply_.reset();
  negotiator_.reset();
}

void camera_controller::emit_leader_changed(int leader, int previous, std::string_view reason,
                                            controller_output& out) const {
  emit(out, events::leader_changed{.task = task_->task,
                                   .leader = leader,
                                   .previous = previous,
                                   .reason = std::string(reason),
                                   .term = term_});
}

void camera_controller::leave_task(std::string_view reason, controller_output& out) {
  if (!task_) return;
  // Nothing more about a cancelled task: its leader hears the cancellation itself.
  if (role_ == group_role::member && cancelled_.count(task_->task) == 0) {
    auto last = own_status();
    last.leaving = true;
    send(leader_, last, out);
  }
  emit(out, events::left_task{.task = task_->task,
                              .reason = std::string(reason),
                              .role = role_ == group_role::leader ? "leader" : "member"});
  if (role_ == group_role::leader && members_.empty())
    emit(out, events::group_vanished{.task = task_->task});
  task_.reset();
  handed_over_at_.reset();
  forget_group();
}

void camera_controller::become_leader(std::string_view reason, controller_output& out,
                                      std::optional<protocol::term_epoch> term) {
  const int previous = leader_;
  role_ = group_role::leader;
  leader_ = me_.id;
  term_ = term.value_or(next_term(task_->task));
  heard_term(task_->task, term_);
  handed_over_at_.reset();
  forget_group();
  next_auction_at_ = now_;
  emit_leader_changed(me_.id, previous, reason, out);
}

void camera_controller::follow_leader(int leader, protocol::term_epoch term,
                                      std::string_view reason, controller_output& out) {
  const int previous = leader_;
  role_ = group_role::member;
  leader_ = leader;
  term_ = term;
  heard_term(task_->task, term);
  last_leader_status_ = now_;
  leader_members_.reset();
  handed_over_at_.reset();
  forget_group();
  emit_leader_changed(leader, previous, reason, out);
  // At once, so that the new leader counts this node (and this node's members follow).
  send(protocol::broadcast, own_status(), out);
}

void camera_controller::heard_term(task_id task, protocol::term_epoch term) {
  auto& newest = epochs_[task];
  newest = std::max(newest, term);
}

protocol::term_epoch camera_controller::next_term(task_id task) const {
  auto it = epochs_.find(task);
  const protocol::term_epoch heard = it == epochs_.end() ? 0 : it->second;
  const protocol::term_epoch own = task_ && task_->task == task ? term_ : 0;
  return std::max(heard, own) + 1;
}

void camera_controller::answer_stale(int to, controller_output& out) {
  auto [it, fresh] = answered_stale_.emplace(to, now_);
  if (!fresh && now_ - it->second < ticks(settings_.heartbeat_interval)) return;
  it->second = now_;
  send(to, own_status(), out);
}

void camera_controller::met_other_leader(int other, protocol::term_epoch term, int sender,
                                         controller_output& out) {
  if (term < term_) {
    answer_stale(sender, out);
    return;
  }
  if (term > term_) {
    follow_leader(other, term, "newer_term", out);
    return;
  }
  // Two leaderships of one epoch: the paper's merge rule settles them.
  if (settings_.merge == config::merge_rule::highest_id) {
    // Section IV-C: among conflicting leaders the one with the highest id stays leader; the
    // merge starts a new term, which the other hears as newer.
    if (other > me_.id) {
      follow_leader(other, term, "demoted", out);
    } else {
      term_ = next_term(task_->task);
      heard_term(task_->task, term_);
      emit_leader_changed(me_.id, me_.id, "merged", out);
      send(protocol::broadcast, own_status(), out);
    }
    return;
  }
  negotiator_.met_leader(other, now_);
}

void camera_controller::absorb(int camera, controller_output& out) {
  if (camera == me_.id || members_.count(camera) != 0) return;
  members_[camera] = member_record{0.0, now_, now_};
  emit(out, events::member_change{
                .task = task_->task, .member = camera, .reason = "merge", .added = true});
}

// --- timers ----------------------------------------------------------------------------------

void camera_controller::run_timers(controller_output& out) {
  for (auto it = pending_.begin(); it != pending_.end();) {
    const bool not_found = !it->bid_sent && now_ >= it->look_until;
    const bool expired = now_ >= it->give_up_at;
    if (not_found || expired) {
      emit(out, events::query_dropped{
                    .task = it->task.task,
                    .leader = it->leader,
                    .reason = not_found ? (it->unconfirmed ? "not_confirmed" : "not_found")
                                        : "bidding_timeout"});
      it = pending_.erase(it);
    } else {
      ++it;
    }
  }
  if (!task_) return;
  if (seen_now_) {
    const auto before = fsm_.state();
    const auto cmd = fsm_.step(observation_of(*seen_now_), pose_, me_.frame, tick_);
    out.command = cmd.pose;
    if (cmd.state != before)
      emit(out, events::tracking{.task = task_->task, .state = std::string(name_of(cmd.state))});
  }
  if (fsm_.state() == vision::tracking_state::failed && !handed_over_at_) {
    // Fig. 10: Failed ends the node's part in the task, back to Idle and its default pose. A
    // leader first gives its group to the member that saw her last, so that the group keeps
    // looking for her; until the new leader is heard, it waits as after any hand-over.
    if (role_ == group_role::leader && hand_over(-1.0, out, true)) return;
    leave_task("target_lost", out);
    return;
  }
  if (role_ == group_role::leader) {
    lead(out);
  } else {
    follow(out);
  }
}

void camera_controller::follow(controller_output& out) {
  if (handed_over_at_) {
    // No heartbeat and no leaving on low relevance meanwhile: it would be counted as a member,
    // or leave the task to a leader that may never have it.
    if (now_ - *handed_over_at_ < ticks(settings_.leader_failure_timeout)) return;
    handed_over_at_.reset();
    become_leader("handover_unconfirmed", out);
    lead(out);
    return;
  }
  if (now_ - last_leader_status_ >= ticks(settings_.leader_failure_timeout)) {
    // Section IV-C: no status from the leader in time: it is taken as failed, and this node
    // leads at a new term, so that the failed leader's statuses, if it comes back, are stale.
    become_leader("leader_failed", out);
    lead(out);
    return;
  }
  const bool settled = now_ - joined_ > ticks(settings_.member_failure_timeout);
  if ((settled && relevance(now_) < settings_.membership_relevance_threshold) ||
      fsm_.state() == vision::tracking_state::failed) {
    leave_task("relevance_low", out);
    return;
  }
  if ((now_ - joined_) % ticks(settings_.heartbeat_interval) == 0)
    send(protocol::broadcast, own_status(), out);
}

void camera_controller::lead(controller_output& out) {
  const auto heartbeat = ticks(settings_.heartbeat_interval);
  const auto silence = ticks(settings_.member_failure_timeout);
  // Drop members that went silent or whose relevance decayed below the membership threshold.
  for (auto it = members_.begin(); it != members_.end();) {
    const auto age = now_ - it->second.last_status;
    const bool settled = now_ - it->second.joined > silence;
    const char* why =
        age >= silence ? "silent"
        : settled && decayed(it->second.relevance, age) < settings_.membership_relevance_threshold
            ? "relevance_low"
            : nullptr;
    if (why == nullptr) {
      ++it;
      continue;
    }
    emit(out,
         events::member_change{
             .task = task_->task, .member = it->first, .reason = std::string(why), .added = false});
    it = members_.erase(it);
  }
  const double mine = relevance(now_);
  if (now_ - joined_ > silence && mine < settings_.membership_relevance_threshold &&
      hand_over(mine, out))
    return;
  if ((now_ - joined_) % heartbeat == 0) send(protocol::broadcast, own_status(), out);
  demotion_negotiator::actions a;
  negotiator_.tick(now_, a);
  apply_demotions(a, out);
  if (!task_ || role_ != group_role::leader) return;
  // The baseline without collaboration: the tasked camera never recruits.
  if (!collaborate_) return;
  if (csp_ && csp_->own_ready && csp_->waiting.empty()) {
    solve_csp(out);
  } else if (csp_ && now_ >= csp_->deadline) {
    // A group that did not answer cannot be settled without: its cameras are its own. The
    // conflict comes back with the next claim.
    std::vector<task_id> missing;
    for (const auto& [leader, t] : csp_->waiting) missing.push_back(t);
    emit(out, events::csp_abandoned{.task = task_->task, .missing = std::move(missing)});
    csp_.reset();
  }
  if (auction_ && now_ >= auction_->closes_at) {
    close_auction(out);
  } else if (!auction_ && !csp_ && now_ >= next_auction_at_) {
    const auto size = 1 + members_.size();
    if (size < task_->max_cameras || mine < settings_.auction_relevance_threshold)
      open_auction(out);
  }
}

bool camera_controller::hand_over(double mine, controller_output& out, bool to_anyone) {
  // Section IV-A: a leader below the threshold selects a new leader among its members; only one
  // that still sees the target better, else this leader keeps the group and searches. A leader
  // whose search failed gives it to its best member whatever that member's relevance.
  auto best = members_.end();
  for (auto it = members_.begin(); it != members_.end(); ++it)
    if (best == members_.end() || it->second.relevance > best->second.relevance) best = it;
  if (best == members_.end()) return false;
  if (!to_anyone && (best->second.relevance < settings_.membership_relevance_threshold ||
                     best->second.relevance <= mine))
    return false;
  const protocol::handover h{.task = *task_,
                             .old_leader = me_.id,
                             .new_leader = best->first,
                             .term = next_term(task_->task),
                             .members = members()};
  for (const auto& [m, rec] : members_) send(m, h, out);
  emit(out, events::handoff{.task = task_->task,
                            .from = me_.id,
                            .to = best->first,
                            .relevance = best->second.relevance});
  // Not gone yet: the hand-over may be lost, or its new leader may have left or failed since
  // its last status; until the new leader is heard leading, this node is the task's only keeper.
  // (No leader_changed here: the new leader logs the change when it takes the group.)
  role_ = group_role::member;
  leader_ = best->first;
  term_ = h.term;
  heard_term(task_->task, term_);
  last_leader_status_ = now_;
  leader_members_.reset();
  forget_group();
  handed_over_at_ = now_;
  return true;
}

// --- auctions (Fig. 13) ----------------------------------------------------------------------

void camera_controller::open_auction(controller_output& out) {
  auction_state a;
  a.id = next_auction_id_++;
  a.closes_at = now_ + ticks(settings_.auction_window);
  protocol::query_relevance q{
      .task = *task_, .leader = me_.id, .term = term_, .auction = a.id, .relay = false};
  send(protocol::broadcast, q, out);
  q.relay = true;
  for (const auto& [m, rec] : members_) send(m, q, out);
  emit(out, events::auction_started{.task = task_->task,
                                    .auction = a.id,
                                    .group_size = 1 + members_.size(),
                                    .relevance = relevance(now_)});
  auction_ = std::move(a);
}

void camera_controller::close_auction(controller_output& out) {
  std::vector<protocol::relevance_bid> free;
  last_bids_.clear();
  if (auction_->for_conflict) {
    // It gathered relevances: the CSP, not this auction, chooses.
    for (const auto& [bidder, b] : auction_->bids)
      if (bidder != me_.id && members_.count(bidder) == 0) last_bids_.push_back(b);
    emit(out, events::auction_closed{.task = task_->task,
                                     .auction = auction_->id,
                                     .bids = auction_->bids.size(),
                                     .chosen = {}});
    auction_.reset();
    next_auction_at_ = now_ + config::to_ticks(settings_.auction_interval, tick_);
    if (csp_reply_) {
      send(csp_reply_->solver,
           own_csp_data(csp_reply_->round, {task_->task, csp_reply_->solver_task}), out);
      csp_reply_.reset();
    }
    if (csp_) csp_->own_ready = true;
    return;
  }
  for (const auto& [bidder, b] : auction_->bids) {
    if (bidder == me_.id || members_.count(bidder) != 0) continue;
    last_bids_.push_back(b);
    if (!b.busy) free.push_back(b);
  }
  std::sort(free.begin(), free.end(), better_bid);
  const auto size = 1 + members_.size();
  std::size_t slots = task_->max_cameras > size ? task_->max_cameras - size : 0;
  // Handoff: a leader losing its target takes one camera beyond the group's size.
  if (slots == 0 && relevance(now_) < settings_.auction_relevance_threshold) slots = 1;
  std::vector<int> chosen;
  for (const auto& b : free) {
    if (chosen.size() == slots) break;
    chosen.push_back(b.bidder);
  }
  emit(out, events::auction_closed{.task = task_->task,
                                   .auction = auction_->id,
                                   .bids = auction_->bids.size(),
                                   .chosen = chosen});
  auction_.reset();
  next_auction_at_ = now_ + config::to_ticks(settings_.auction_interval, tick_);
  for (int c : chosen) invite(c, false, out);
  // Section IV-B: busy cameras only through the CSP, which each busy bidder initiates itself
  // (weigh_evidence).
}

void camera_controller::invite(int camera, bool reassign, controller_output& out) {
  const protocol::join j{
      .task = *task_, .leader = me_.id, .term = term_, .invitee = camera, .reassign = reassign};
  send(camera, j, out);
  if (auto via = relayed_by_.find(camera); via != relayed_by_.end() && members_.count(via->second))
    send(via->second, j, out);
  // Counted at once; a camera that does not join sends no status and is dropped as silent.
  double r = 0.0;
  for (const auto& b : last_bids_)
    if (b.bidder == camera) r = b.relevance;
  members_[camera] = member_record{r, now_, now_};
  emit(out, events::invited{.task = task_->task, .member = camera, .reassign = reassign});
}

// --- conflict resolution (Section IV-B, Fig. 14) ---------------------------------------------

protocol::status camera_controller::own_status() const {
  protocol::status s;
  s.task = task_->task;
  s.sender = me_.id;
  s.leader = leader_;
  s.term = term_;
  s.relevance = relevance(now_);
  s.min_cameras = task_->min_cameras;
  s.max_cameras = task_->max_cameras;
  if (role_ == group_role::leader) s.members = members();
  return s;
}

protocol::csp_data camera_controller::own_csp_data(std::uint32_t round,
                                                   const std::set<task_id>& tasks) const {
  protocol::csp_data d;
  d.task = *task_;
  d.leader = me_.id;
  d.term = term_;
  d.round = round;
  d.candidates.push_back({me_.id, relevance(now_)});
  d.members.push_back(me_.id);
  if (now_ < pinned_until_) d.pinned.push_back(me_.id);
  for (const auto& [m, rec] : members_) {
    d.candidates.push_back({m, rec.relevance});
    d.members.push_back(m);
    if (now_ < rec.pinned_until) d.pinned.push_back(m);
  }
  // A bidder busy in a group outside the conflict is that group's to give, not this one's.
  for (const auto& b : last_bids_) {
    const bool elsewhere = b.busy && (!b.other_task || tasks.count(*b.other_task) == 0);
    if (members_.count(b.bidder) == 0 && !b.locked && !elsewhere)
      d.candidates.push_back({b.bidder, b.relevance});
  }
  return d;
}

void camera_controller::report_conflict(std::vector<protocol::conflict_claim> claims,
                                        controller_output& out) {
  std::sort(claims.begin(), claims.end(),
            [](const auto& a, const auto& b) { return a.task < b.task; });
  std::vector<task_id> tasks;
  for (const auto& c : claims) tasks.push_back(c.task);
  const int solver = claims.front().leader;
  emit(out, events::conflict_reported{.task = claims.front().task, .tasks = tasks, .to = solver});
  protocol::csp_conflict c{.camera = me_.id, .claims = std::move(claims)};
  if (solver == me_.id) {
    on_csp_conflict(c, out);
  } else {
    send(solver, std::move(c), out);
  }
}

void camera_controller::on_csp_conflict(const protocol::csp_conflict& c, controller_output& out) {
  if (!collaborate_ || !task_ || role_ != group_role::leader || c.claims.empty()) return;
  const auto lowest = std::min_element(c.claims.begin(), c.claims.end(),
                                       [](auto& a, auto& b) { return a.task < b.task; });
  if (lowest->task != task_->task) return;
  std::map<int, task_id> leaders;
  std::map<task_id, std::vector<protocol::camera_relevance>> said;
  for (const auto& k : c.claims) {
    if (cancelled_.count(k.task) != 0) continue;
    said[k.task].push_back({c.camera, k.relevance});
    if (k.task != task_->task && k.leader != me_.id) leaders[k.leader] = k.task;
  }
  if (leaders.empty()) return;
  if (csp_) {
    // One conflict at a time: what is said while its relevances are still being gathered
    // joins it, if it is about its groups.
    if (csp_->own_ready) return;
    for (const auto& [t, cameras] : said)
      if (csp_->tasks.count(t) != 0)
        csp_->claims[t].insert(csp_->claims[t].end(), cameras.begin(), cameras.end());
    return;
  }
  start_csp(leaders, said, out);
}

void camera_controller::start_csp(
    const std::map<int, task_id>& leaders,
    const std::map<task_id, std::vector<protocol::camera_relevance>>& claims,
    controller_output& out) {
  std::set<task_id> tasks{task_->task};
  for (const auto& [leader, t] : leaders) tasks.insert(t);
  std::set<int> cameras;
  for (const auto& [t, said] : claims)
    for (const auto& c : said) cameras.insert(c.camera);
  // Table 2's minimum duration for an assigned task: a conflict just settled is not settled
  // again until then, unless a task or a camera joins it.
  if (settled_ && settled_->tasks == tasks &&
      now_ - settled_->at < ticks(settings_.min_task_duration) &&
      std::includes(settled_->cameras.begin(), settled_->cameras.end(), cameras.begin(),
                    cameras.end()))
    return;
  csp_round round;
  round.round = next_csp_round_++;
  // The others answer when their gathering auction closes.
  round.deadline = now_ + ticks(settings_.auction_window) + 2 * ticks(message_timeout_);
  round.waiting = leaders;
  round.tasks = tasks;
  round.claims = claims;
  for (const auto& [leader, t] : leaders)
    send(leader,
         protocol::csp_query{
             .solver_task = task_->task, .solver = me_.id, .term = term_, .round = round.round},
         out);
  std::vector<task_id> others;
  for (task_id t : tasks)
    if (t != task_->task) others.push_back(t);
  emit(out, events::conflict{.task = task_->task,
                             .with_tasks = std::move(others),
                             .cameras = {cameras.begin(), cameras.end()}});
  csp_ = std::move(round);
  open_gathering(out);
}

void camera_controller::open_gathering(controller_output& out) {
  // Fig. 19: "the two cameras pan out to search for the latter" — every camera of the groups
  // hears every task's query, and those that find its target say how relevant they are.
  if (!auction_) open_auction(out);
  auction_->for_conflict = true;
}

void camera_controller::on_csp_query(int from, const protocol::csp_query& q,
                                     controller_output& out) {
  if (!task_ || role_ != group_role::leader || q.solver_task == task_->task) return;
  if (csp_) {
    // Two leaders centralising the same conflict: the lower task id solves it.
    if (task_->task < q.solver_task) return;
    emit(out, events::csp_yielded{.task = task_->task, .to_task = q.solver_task});
    csp_.reset();
  }
  csp_reply_ = csp_reply{.solver = from, .solver_task = q.solver_task, .round = q.round};
  open_gathering(out);
}

void camera_controller::on_csp_data(const protocol::csp_data& d, controller_output&) {
  if (!csp_ || d.round != csp_->round || csp_->waiting.erase(d.leader) == 0) return;
  csp_->data.push_back(d);
}

void camera_controller::solve_csp(controller_output& out) {
  auto claimed = [&](protocol::csp_data d) {
    if (auto it = csp_->claims.find(d.task.task); it != csp_->claims.end())
      d.candidates.insert(d.candidates.end(), it->second.begin(), it->second.end());
    return d;
  };
  std::vector<protocol::csp_data> groups{claimed(own_csp_data(csp_->round, csp_->tasks))};
  for (const auto& d : csp_->data) groups.push_back(claimed(d));
  const auto built =
      build_csp(groups, settings_.membership_relevance_threshold, settings_.conflict_stay_bonus);
  const auto solution =
      protocol::solve(built.problem, solver_kind(settings_.solver), run_csp_limits);
  const auto plan = built.plan(solution);
  events::csp_solved e{.task = task_->task,
                       .solver = std::string(config::yaml_name(settings_.solver)),
                       .groups = built.groups.size(),
                       .cameras = built.cameras.size(),
                       .weight = solution.weight,
                       .nodes_explored = solution.nodes_explored,
                       .backtracks = solution.backtracks,
                       .relaxed = solution.relaxed,
                       .minima = {},
                       .optimal = solution.proven_optimal,
                       .tasks = {},
                       .camera_ids = built.cameras,
                       .min_cameras = {},
                       .max_cameras = {},
                       .relevance = {},
                       .staying = built.fixed,
                       .leaders = {},
                       .assigned = {}};
  for (std::size_t g = 0; g < built.groups.size(); ++g) {
    const auto& group = built.problem.groups[g];
    e.tasks.push_back(built.groups[g].task.task);
    e.minima.emplace_back(built.groups[g].task.task,
                          g < solution.minima.size() ? solution.minima[g] : 0u);
    e.min_cameras.push_back(group.min_cameras);
    e.max_cameras.push_back(group.max_cameras);
    std::vector<events::fixed<6>> row;
    for (double r : group.relevance) row.emplace_back(std::isnan(r) ? -1.0 : r);
    e.relevance.push_back(std::move(row));
    e.leaders.push_back(plan[g].leader);
    std::vector<int> cameras;
    for (const auto& m : plan[g].members) cameras.push_back(m.camera);
    e.assigned.push_back(std::move(cameras));
  }
  emit(out, std::move(e));
  protocol::csp_result r{.solver_task = task_->task,
                         .solver = me_.id,
                         .term = term_,
                         .round = csp_->round,
                         .groups = plan};
  // Every camera the solver weighed, and every leader: each takes its own place.
  std::set<int> told;
  for (std::size_t g = 0; g < built.groups.size(); ++g) {
    told.insert(built.groups[g].leader);
    for (const auto& c : built.reported[g]) told.insert(c.camera);
  }
  settled_ = settled_conflict{.tasks = csp_->tasks, .cameras = told, .at = now_};
  csp_.reset();
  for (int c : told)
    if (c != me_.id) send(c, r, out);
  take_place(r, out);
}

void camera_controller::retell_place(const protocol::status& s, controller_output& out) {
  for (const auto& g : last_result_->groups) {
    const bool named =
        g.leader == s.sender || std::any_of(g.members.begin(), g.members.end(),
                                            [&](const auto& m) { return m.camera == s.sender; });
    if (!named) continue;
    const bool in_place = s.task == g.task.task && (s.leader == g.leader || s.term > g.term);
    if (in_place) return;
    // It is where it was: the result did not reach it (lost). Told again, at most twice.
    auto& told = results_retold_[s.sender];
    if (told >= 2) return;
    ++told;
    send(s.sender, *last_result_, out);
    return;
  }
}

void camera_controller::on_csp_result(const protocol::csp_result& r, controller_output& out) {
  if (results_taken_.count({r.solver, r.round}) != 0) return;
  take_place(r, out);
}

void camera_controller::take_place(const protocol::csp_result& r, controller_output& out) {
  results_taken_.insert({r.solver, r.round});
  last_result_ = r;
  // Long enough for a node that missed it to be heard (a heartbeat, a status's delay), short
  // enough that a node that has since crashed and come back, with nothing in memory, is not
  // sent an old decision and its ended terms.
  last_result_until_ =
      now_ + ticks(settings_.member_failure_timeout) + ticks(settings_.leader_failure_timeout);
  results_retold_.clear();
  const protocol::csp_assignment* mine = nullptr;
  bool concerned = false;
  for (const auto& g : r.groups) {
    if (cancelled_.count(g.task.task) != 0) continue;
    heard_term(g.task.task, g.term);
    if (task_ && task_->task == g.task.task) concerned = true;
    const bool member = std::any_of(g.members.begin(), g.members.end(),
                                    [&](const auto& m) { return m.camera == me_.id; });
    if (g.leader == me_.id || member) mine = &g;
  }
  // A result older than the leadership this node follows in its task is not its to take.
  if (task_ && mine && mine->task.task == task_->task && term_ > mine->term) return;
  if (!mine) {
    if (concerned) leave_task("reassigned", out);
    return;
  }
  const auto t = mine->task.task;
  std::vector<int> cameras{mine->leader};
  for (const auto& m : mine->members) cameras.push_back(m.camera);
  emit(out, events::csp_applied{.task = t, .solver_camera = r.solver, .cameras = cameras});
  const bool same_task = task_ && task_->task == t;
  const auto pin = now_ + ticks(settings_.min_task_duration);
  if (mine->leader == me_.id) {
    if (!same_task) {
      if (task_) leave_task("reassigned", out);
      pending_.clear();
      // Past every epoch this node has heard of the task, as any new leadership.
      const auto term = std::max(mine->term, next_term(t));
      start_task(mine->task, group_role::leader, me_.id, mine->relevance, now_, term, out);
      pinned_until_ = pin;
      emit(out, events::joined{.task = t, .leader = me_.id, .reassign = true, .term = term_});
      emit_leader_changed(me_.id, mine->previous, "conflict", out);
    } else if (role_ != group_role::leader) {
      const auto term = std::max(mine->term, next_term(t));
      role_ = group_role::leader;
      leader_ = me_.id;
      term_ = term;
      handed_over_at_.reset();
      forget_group();
      pinned_until_ = pin;
      emit_leader_changed(me_.id, mine->previous, "conflict", out);
    } else {
      term_ = std::max(term_, mine->term);
    }
    for (auto it = members_.begin(); it != members_.end();) {
      const bool kept = std::any_of(mine->members.begin(), mine->members.end(),
                                    [&](const auto& m) { return m.camera == it->first; });
      if (kept) {
        ++it;
        continue;
      }
      emit(out, events::member_change{
                    .task = t, .member = it->first, .reason = "reassigned", .added = false});
      it = members_.erase(it);
    }
    for (const auto& m : mine->members) {
      if (members_.count(m.camera) != 0) continue;
      members_[m.camera] = member_record{m.relevance, now_, now_, pin};
      emit(out, events::member_change{
                    .task = t, .member = m.camera, .reason = "conflict", .added = true});
    }
    send(protocol::broadcast, own_status(), out);
    return;
  }
  if (same_task) {
    if (role_ == group_role::member && leader_ == mine->leader) {
      term_ = std::max(term_, mine->term);
      return;
    }
    follow_leader(mine->leader, mine->term, "conflict", out);
    return;
  }
  double r_mine = 0.0;
  for (const auto& m : mine->members)
    if (m.camera == me_.id) r_mine = m.relevance;
  if (task_) leave_task("reassigned", out);
  pending_.clear();
  start_task(mine->task, group_role::member, mine->leader, r_mine, now_, mine->term, out);
  pinned_until_ = pin;
  emit(out, events::joined{.task = t, .leader = mine->leader, .reassign = true, .term = term_});
  send(protocol::broadcast, own_status(), out);
}

// --- the next frame --------------------------------------------------------------------------

const camera_controller::pending_query* camera_controller::followed_query() const {
  if (!settings_.track_while_bidding || task_) return nullptr;
  // Until the join could have come: the auction closes within its window of the query, and
  // the join takes up to a message timeout to arrive.
  const auto wait = ticks(settings_.auction_window) + ticks(message_timeout_);
  for (const auto& p : pending_) {
    if (!p.first_found || p.unconfirmed) continue;
    if (p.bid_sent ? now_ - p.bid_at <= wait : now_ < p.look_until) return &p;
  }
  return nullptr;
}

bool camera_controller::follow_find(controller_output& out) {
  const auto* p = followed_query();
  if (p == nullptr) {
    bid_followed_.reset();
    return false;
  }
  if (bid_followed_ != p->task.task) {
    bid_fsm_.reset();
    bid_followed_ = p->task.task;
  }
  if (bid_seen_)
    out.command = bid_fsm_.step(observation_of(*bid_seen_), pose_, me_.frame, tick_).pose;
  return true;
}

void camera_controller::plan_next(controller_output& out) {
  if (task_) out.looks.push_back(look_request{task_->task, task_->target});
  const bool following = follow_find(out);
  for (const auto& p : pending_) {
    // follow_find() leaves bid_followed_ set only while it follows.
    const bool followed = bid_followed_ == p.task.task;
    if (!followed && (p.bid_sent || now_ >= p.look_until)) continue;
    const bool asked = std::any_of(out.looks.begin(), out.looks.end(),
                                   [&](const look_request& l) { return l.task == p.task.task; });
    if (!asked) out.looks.push_back(look_request{p.task.task, p.task.target});
  }
  // Section III-C: a camera with no task returns to its default pose (the reset routine); one
  // that follows a find while bidding, or looks for one, returns once it no longer does.
  const bool holds = settings_.track_while_bidding ? following : !pending_.empty();
  // A failed search holds nothing either: a leader waiting to hear its hand-over taken up
  // already turns home.
  const bool failed = task_ && fsm_.state() == vision::tracking_state::failed;
  if ((failed || (!task_ && !holds)) && !(pose_ == me_.home)) out.command = me_.home;
}

}  // namespace argus::controller
