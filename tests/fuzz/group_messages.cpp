// Fuzzes protocol::decode, the only reader of bytes that come from other nodes.
//
// Input: KIND '\n' BODY (no '\n': all of it is the kind, the body empty). Whatever decodes must
// be of that kind, encode to bytes that decode to an equal message, and those bytes must be the
// message's one encoding (encoding the copy gives them again).

#include "protocol/group_messages.hpp"

#include <string>

#include "tests/fuzz/fuzz_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace argus::protocol;
  const auto input = argus::fuzz::text_of(data, size);
  const auto split = input.find('\n');
  const auto kind = input.substr(0, split);
  const auto body = split == std::string_view::npos ? std::string_view{} : input.substr(split + 1);
  const auto message = decode(kind, body);
  if (!message) return 0;
  ARGUS_FUZZ_CHECK(is_group_kind(kind));
  ARGUS_FUZZ_CHECK(kind_of(*message) == kind);
  (void)task_of(*message);
  const auto bytes = encode(*message);
  const auto again = decode(kind, bytes);
  ARGUS_FUZZ_CHECK(again.has_value());
  ARGUS_FUZZ_CHECK(*again == *message);
  ARGUS_FUZZ_CHECK(encode(*again) == bytes);
  return 0;
}
