// The whole process of the floor (bench/terrain_floor.hpp): the 3R smooth circle run of 200 s
// and its 2,001 CSV rows of sphere_sim's 17 columns, with the scenario compiled in (nothing read,
// nothing checked). scripts/run_benchmarks.sh times it as a process beside `sphere_sim terrain`:
// what is left of issue 13's 10 ms for reading the scenario, checking inputs and structure.
// usage: bench_terrain_floor OUT.csv

#include <charconv>
#include <cstdio>

#include "terrain_floor.hpp"

int main(int argc, char** argv) {
  using namespace spherical_robots::bench;
  if (argc != 2) {
    std::fprintf(stderr, "usage: bench_terrain_floor OUT.csv\n");
    return 2;
  }
  std::FILE* out = std::fopen(argv[1], "w");
  if (out == nullptr) {
    std::perror(argv[1]);
    return 1;
  }
  std::fputs("t,x0,y0,z0,xd,yd,zd,e_norm,zeta,psi,phi,cx,cy,cz,roll_rate,lateral_rate,turn_rate\n",
             out);
  const FloorScenario scenario;
  constexpr double kRadius = 0.2;  // urdf/terrain_robot.urdf's shell
  const auto write_row = [&](double t, const std::array<double, 3>& state, const FloorDesired& d) {
    FloorRow r{};
    floorStateRate<true>(scenario, state.data(), d, kRadius, &r);
    const double values[] = {t,         state[0],    state[1],    r.height,    d.p[0],
                             d.p[1],    d.p[2],      r.error_norm, r.zeta,     state[2],
                             0.0,       r.centre[0], r.centre[1], r.centre[2], r.roll_rate,
                             r.lateral_rate, r.turn_rate};
    char line[17 * 32];
    char* end = line;
    for (double value : values) {
      end = std::to_chars(end, line + sizeof line, value).ptr;
      *end++ = ',';
    }
    end[-1] = '\n';
    std::fwrite(line, 1, end - line, out);
  };
  const auto final_state = runFloor(scenario, 40000, 0.005, 20, write_row);
  std::fclose(out);
  std::printf("floor: 3R circle 200 s, law smooth: final x %.6f m, y %.6f m, psi %.6f rad\n",
              final_state[0], final_state[1], final_state[2]);
  return 0;
}
