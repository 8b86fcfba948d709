#include "report/world_console.h"

#include <ostream>

#include "report/text_table.h"

namespace tcsb {

void print_world_report(const RunResult& result, std::ostream& out) {
  if (!result.world) return;
  const WorldResult& w = *result.world;
  using Align = TextTable::Align;
  TextTable t({{"method", Align::kLeft},
               {"budget"},
               {"status", Align::kLeft},
               {"mean nodes"},
               {"step ms"},
               {"time/full"},
               {"p95 px"},
               {"pop max px"},
               {"changes"}});
  for (const WorldMethodResult& m : w.methods)
    t.add_row({m.method, fixed(m.budget, 2), m.status, fixed(m.mean_nodes, 1), fixed(m.step_ms, 3),
               fixed(m.step_ratio, 3), fixed(m.p95_px, 2), fixed(m.popping_px, 2),
               std::to_string(m.resolution_changes)});
  out << "World pass: " << w.bodies << " bodies, " << w.scene_nodes
      << " nodes at full resolution; p95 px = the 95th percentile of the pixel error over every point of every body "
         "the camera sees, mean over steps; time/full = median over blocks of the step's ratio to full resolution's; "
         "pop = the largest jump on the image where a body changed its resolution\n";
  t.print(out);
}

}  // namespace tcsb
