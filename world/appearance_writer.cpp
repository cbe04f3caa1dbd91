#include "world/appearance_writer.hpp"

#include <fmt/format.h>

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
  for (const auto& p : frame.pedestrians()) {
    if (!written_.insert(p.id).second) continue;
    const auto& look = p.look;
    fmt::format_to(std::back_inserter(buffer), "{},{},{},{},{},{},{},{}\n", p.id, frame.tick(),
                   hex(look.shirt), hex(look.trousers), hex(look.skin), hex(look.hair),
                   look.height_m, look.girth_m);
  }
  out_ << buffer;
}

}  // namespace argus::world
