#pragma once

#include <string>

#include "protocol/message_accounting.hpp"

namespace argus::actors {

/// A link's answer to `(report_atom)` at the end of a run: what became of every message it
/// carried (messages still pending count as in flight).
struct link_report {
  std::string link;
  protocol::accounting_by_kind counts;
};

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, link_report& x) {
  return f(x.link, x.counts);
}

}  // namespace argus::actors
