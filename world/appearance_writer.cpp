#include "world/appearance_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <iterator>
#include <string>

#include "world/snapshot.hpp"

namespace argus::world {
namespace {

std::string hex(const rgb8& c) {
  return fmt::format("#{:02x}{:02x}{:02x}", c.r, c.g, c.b);
}

}  // namespace

appearance_writer::appearance_writer(std::ostream& out) : out_(out) {
  out_ << "id,first_tick,shirt,trousers,skin,hair,height_m,girth_m\n";
}

void appearance_writer::write(const snapshot& frame) {
  std::string buffer;
  int last = last_written_;
  for (const auto& p : frame.pedestrians()) {
    if (p.id <= last_written_) continue;
    last = std::max(last, p.id);
    const auto& look = p.look;
    fmt::format_to(std::back_inserter(buffer), "{},{},{},{},{},{},{},{}\n", p.id, frame.tick(),
                   hex(look.shirt), hex(look.trousers), hex(look.skin), hex(look.hair),
                   look.height_m, look.girth_m);
  }
  last_written_ = last;
  out_ << buffer;
}

}  // namespace argus::world
