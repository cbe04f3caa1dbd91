#pragma once

// The fixture of the CAF protocol tests: CAF's deterministic test coordinator on our actor
// system configuration, with a recorder stand-in that keeps every event in memory. Include it
// after caf/test/dsl.hpp (each test's runner defines CAF_SUITE first).

#include <memory>

#include "actors/system_config.hpp"
#include "tests/actors/test_participants.hpp"

namespace argus::actors::testing {

struct test_config : system_config {
  test_config() : system_config(1) {}
};

struct recording_fixture : test_coordinator_fixture<test_config> {
  std::shared_ptr<recorded> rec = std::make_shared<recorded>();
  caf::actor recorder = sys.spawn(fake_recorder, rec);
};

}  // namespace argus::actors::testing
