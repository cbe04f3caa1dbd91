#include "report/base64.hpp"

#include <gtest/gtest.h>

#include <string_view>

namespace argus::report {
namespace {

std::string of(std::string_view text) {
  return base64(std::span{reinterpret_cast<const unsigned char*>(text.data()), text.size()});
}

// RFC 4648, section 10.
TEST(base64, rfc_4648_test_vectors) {
  EXPECT_EQ(of(""), "");
  EXPECT_EQ(of("f"), "Zg==");
  EXPECT_EQ(of("fo"), "Zm8=");
  EXPECT_EQ(of("foo"), "Zm9v");
  EXPECT_EQ(of("foob"), "Zm9vYg==");
  EXPECT_EQ(of("fooba"), "Zm9vYmE=");
  EXPECT_EQ(of("foobar"), "Zm9vYmFy");
}

TEST(base64, high_bytes) {
  const unsigned char bytes[] = {0xff, 0xfe, 0x00, 0x89};
  EXPECT_EQ(base64(bytes), "//4AiQ==");
}

}  // namespace
}  // namespace argus::report
