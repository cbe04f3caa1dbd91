// Message kinds: names carried as small indices, equal exactly when their names are, and the
// same from any thread.

#include "protocol/message_kind.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <thread>
#include <vector>

namespace argus::protocol {
namespace {

TEST(message_kind, is_its_name) {
  message_kind hello{"hello"};
  EXPECT_EQ(hello.name(), "hello");
  EXPECT_EQ(hello, message_kind{fmt::format("hel{}", "lo")});
  EXPECT_EQ(hello, "hello");
  EXPECT_FALSE(hello == "hell");
  EXPECT_FALSE(hello == message_kind{"queryrelevance"});
  EXPECT_TRUE(message_kind{}.empty());
  EXPECT_EQ(message_kind{""}, message_kind{});
  EXPECT_EQ(fmt::format("[{}]", message_kind{"demote"}), "[demote]");
}

TEST(message_kind, threads_naming_the_same_kinds_get_the_same_kinds) {
  std::vector<std::vector<message_kind>> seen(4);
  std::vector<std::thread> threads;
  for (std::size_t t = 0; t < seen.size(); ++t)
    threads.emplace_back([&, t] {
      for (int i = 0; i < 200; ++i) seen[t].push_back(message_kind{fmt::format("k{}", i)});
    });
  for (auto& th : threads) th.join();
  for (std::size_t t = 1; t < seen.size(); ++t) EXPECT_EQ(seen[t], seen[0]);
  std::set<std::string> names;
  for (const auto& k : seen[0]) names.insert(k.name());
  EXPECT_EQ(names.size(), 200u);
}

}  // namespace
}  // namespace argus::protocol
