// Where a suite's calibration file lives: its fidelity.calibration, relative to the suite file, and never outside
// the suite's directory tree. `tcsb calibrate` writes that file, so a suite that could name "../../x", an absolute
// path or a symlink leading out could make the tool overwrite any file the user may write; reading it from there
// would let a suite pull in what does not travel with it.
#pragma once

#include <filesystem>
#include <string>

namespace tcsb {

/// The calibration file a suite read from `suite_file` names with `named` (its fidelity.calibration): the suite's
/// directory / `named`. Throws InputError naming `suite_file` and fidelity.calibration when `named` is absolute,
/// has a ".." component, or resolves (through a symlink of the file or of a directory on the way) to a path outside
/// the suite's directory. The file need not exist (`tcsb calibrate` creates it).
std::filesystem::path calibration_file_path(const std::filesystem::path& suite_file, const std::string& named);

}  // namespace tcsb
