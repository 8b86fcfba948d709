// The speed-up at equal error (paper/equal_error_table.h) as native JSON: one net's, or the world pass's scene's,
// curves and rows. The fidelity section (report/fidelity_json.h) and the world section (report/world_json.h) write it.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "paper/equal_error_table.h"

namespace tcsb {

/// A row, case or curve point of full resolution names its divisor; no other writes it (older results stay as they
/// were).
void add_solver_divisor(const std::string& method, int divisor, nlohmann::ordered_json& out);

/// `net`'s curves and rows; `grid_rival` names the grid-like rival's curve and column ("uniform_grid" in the fidelity
/// pass, "discrete_lod" in the world pass).
nlohmann::ordered_json equal_error_json(const EqualErrorNet& net, const std::string& grid_rival);

}  // namespace tcsb
