// The classic method's count and the columns of measurements.csv: the classic method's keep
// their places, the Voronoi method's follow.
#include "world/measurement.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "world/experiment_layouts.hpp"
#include "world/snapshot.hpp"
#include "world/station.hpp"

namespace argus::world {
namespace {

/// People 1 m apart on [3, 7] x [3, 6] (centres at the half metres), walking east at 1.2 m/s.
snapshot metre_lattice() {
  static const station room(bottleneck_room_layout(1.0));
  std::vector<pedestrian_state> people;
  for (int row = 0; row < 10; ++row) {
    for (int column = 0; column < 10; ++column) {
      pedestrian_state p;
      p.id = row * 10 + column + 1;
      p.position = {column + 0.5, row + 0.5};
      p.velocity = {1.2, 0.0};
      people.push_back(p);
    }
  }
  return snapshot(room, 10, std::chrono::duration<double>{2.0}, std::move(people));
}

TEST(measurement, classic_method_counts_centres_in_the_area) {
  const auto m = measure_area(metre_lattice(), {{3.0, 3.0}, {7.0, 6.0}});
  EXPECT_EQ(m.count, 12u);
  EXPECT_DOUBLE_EQ(m.density_per_m2, 1.0);
  EXPECT_DOUBLE_EQ(m.speed_mps, 1.2);
  EXPECT_DOUBLE_EQ(m.specific_flow_per_m_s, 1.2);
}

TEST(measurement, writer_appends_the_voronoi_columns) {
  std::ostringstream csv;
  measurement_writer writer(csv);
  const std::vector<named_area> areas{{"middle", {{3.0, 3.0}, {7.0, 6.0}}}};
  writer.write(metre_lattice(), areas);
  std::istringstream lines(csv.str());
  std::string header;
  std::string row;
  std::getline(lines, header);
  std::getline(lines, row);
  EXPECT_EQ(header,
            "t,area,count,density_per_m2,speed_mps,specific_flow_per_m_s,voronoi_density_per_m2,"
            "voronoi_speed_mps,voronoi_specific_flow_per_m_s");
  std::vector<std::string> fields;
  std::istringstream cells(row);
  for (std::string field; std::getline(cells, field, ',');) fields.push_back(field);
  ASSERT_EQ(fields.size(), 9u) << row;
  EXPECT_EQ(fields[0], "2");
  EXPECT_EQ(fields[1], "middle");
  EXPECT_EQ(fields[2], "12");
  EXPECT_NEAR(std::stod(fields[3]), 1.0, 1e-12);
  EXPECT_NEAR(std::stod(fields[6]), 1.0, 1e-6);
  EXPECT_NEAR(std::stod(fields[7]), 1.2, 1e-6);
  EXPECT_NEAR(std::stod(fields[8]), 1.2, 1e-6);
}

}  // namespace
}  // namespace argus::world
