// The protocol's messages on the wire: every kind survives its encoding, and bytes that are
// not a whole, valid message are refused rather than half-read.

#include "protocol/group_messages.hpp"

#include <gtest/gtest.h>

namespace argus::protocol {
namespace {

task_description a_task() {
  task_description t;
  t.task = 3;
  t.target.values.assign(256, 0.0f);
  t.target.values[10] = 0.25f;
  t.target.values[200] = 0.75f;
  t.min_cameras = 2;
  t.max_cameras = 3;
  return t;
}

task_description a_task_with_halves() {
  auto t = a_task();
  t.target.upper.assign(256, 0.0f);
  t.target.lower.assign(256, 0.0f);
  t.target.upper[10] = 1.0f;
  t.target.lower[200] = 1.0f;
  return t;
}

std::vector<group_message> one_of_each() {
  // Every term a different value, so that a field dropped or swapped on the wire shows.
  relevance_bid bid{3, 1, 11, 4, 9, 0.625, true, false, 5u, 6};
  return {query_relevance{a_task(), 1, 12, 4, true},
          bid,
          join{a_task(), 1, 13, 9, true},
          status{3, 9, 1, 14, 0.5, 2, 3, {2, 9}, true},
          handover{a_task(), 1, 9, 15, {2, 9}},
          demotion{demotion_step::demote, 3, 1, 16, {}},
          demotion{demotion_step::ack, 3, 1, 17, {4, 5}},
          demotion{demotion_step::nack, 3, 1, 18, {}},
          demotion{demotion_step::retry, 3, 1, 19, {}},
          csp_conflict{9, {{3, 1, 24, 0.5}, {4, 2, 25, 0.75}}},
          csp_query{3, 1, 20, 2},
          csp_data{a_task(), 1, 21, 2, {{4, 0.5}, {5, 0.25}}, {1, 4}, {4}},
          csp_result{3, 1, 22, 7, {{a_task(), 4, 26, 1, 0.5, {{5, 0.25}, {6, 0.125}}, 1}}},
          task_cancel{3, 1},
          query_relevance{a_task_with_halves(), 1, 23, 4, false},
          note{3, 1, "hello", std::string("\0\x01bytes", 7)}};
}

TEST(group_messages, every_kind_survives_its_encoding) {
  for (const auto& m : one_of_each()) {
    const auto back = decode(kind_of(m), encode(m));
    ASSERT_TRUE(back) << kind_of(m);
    EXPECT_EQ(*back, m) << kind_of(m);
  }
}

TEST(group_messages, a_signature_carries_its_halves_only_when_it_has_them) {
  const auto plain = join{a_task(), 1, 13, 9, true};
  const auto halved = join{a_task_with_halves(), 1, 13, 9, true};
  const auto back = decode("join", encode(halved));
  ASSERT_TRUE(back);
  EXPECT_EQ(*back, group_message{halved});
  // Two more sparse histograms of one filled bin each: a count and an (index, value) apiece.
  EXPECT_EQ(encode(halved).size(), encode(plain).size() + 2 * (2 + 2 + 4));
  const auto plain_back = decode("join", encode(plain));
  ASSERT_TRUE(plain_back);
  EXPECT_TRUE(std::get<join>(*plain_back).task.target.upper.empty());
}

TEST(group_messages, the_paper_names_the_kinds) {
  auto all = one_of_each();
  EXPECT_EQ(kind_of(all[0]), "queryrelevance");
  EXPECT_EQ(kind_of(all[1]), "relevance");
  EXPECT_EQ(kind_of(all[2]), "join");
  EXPECT_EQ(kind_of(all[3]), "status");
  EXPECT_EQ(kind_of(all[6]), "demoteack");
  EXPECT_EQ(kind_of(all[7]), "demotenack");
  EXPECT_EQ(kind_of(all[8]), "demoteretry");
  EXPECT_EQ(kind_of(all[9]), "cspconflict");
  EXPECT_EQ(task_of(all[9]), 3u);  // the lowest task claimed: its leader centralises
}

TEST(group_messages, truncated_or_padded_bytes_are_refused) {
  for (const auto& m : one_of_each()) {
    const auto bytes = encode(m);
    for (std::size_t n = 0; n < bytes.size(); ++n)
      EXPECT_FALSE(decode(kind_of(m), bytes.substr(0, n))) << kind_of(m) << " cut at " << n;
    EXPECT_FALSE(decode(kind_of(m), bytes + "x")) << kind_of(m);
  }
}

TEST(group_messages, a_note_longer_than_its_count_is_refused_not_cut) {
  EXPECT_EQ(kind_of(note{}), "note");
  EXPECT_THROW(encode(note{1, 2, "t", std::string(70000, 'x')}), std::length_error);
  const auto full = note{1, 2, "t", std::string(65535, 'x')};
  EXPECT_EQ(decode("note", encode(full)), group_message{full});
}

TEST(group_messages, out_of_range_values_are_refused) {
  auto bid = relevance_bid{3, 1, 1, 4, 9, 1.5, false, false, std::nullopt, 0};
  EXPECT_FALSE(decode("relevance", encode(bid)));
  auto q = query_relevance{a_task(), 1, 1, 4, false};
  q.task.min_cameras = 4;  // more than the maximum
  EXPECT_FALSE(decode("queryrelevance", encode(q)));
  EXPECT_FALSE(decode("nosuchkind", encode(bid)));
  // A conflict is two claims or more, each with a relevance.
  EXPECT_FALSE(decode("cspconflict", encode(csp_conflict{9, {{3, 1, 1, 0.5}}})));
  EXPECT_FALSE(decode("cspconflict", encode(csp_conflict{9, {{3, 1, 1, 0.5}, {4, 2, 1, 2.0}}})));
  EXPECT_FALSE(decode("cspresult",
                      encode(csp_result{3, 1, 1, 1, {{a_task(), 4, 2, 1, 0.5, {{5, -0.5}}, 1}}})));
}

}  // namespace
}  // namespace argus::protocol
