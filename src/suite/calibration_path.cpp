#include "suite/calibration_path.h"

#include <algorithm>

#include "base/input_error.h"

namespace tcsb {
namespace {

/// Whether `inside` is `dir` or lies below it (both canonical).
bool within(const std::filesystem::path& dir, const std::filesystem::path& inside) {
  const auto [d, i] = std::mismatch(dir.begin(), dir.end(), inside.begin(), inside.end());
  return d == dir.end();
}

}  // namespace

std::filesystem::path calibration_file_path(const std::filesystem::path& suite_file, const std::string& named) {
  const auto fail = [&](const std::string& problem) {
    throw InputError(suite_file.string(), "fidelity.calibration", problem);
  };
  const std::filesystem::path relative(named);
  if (relative.has_root_name() || relative.has_root_directory())
    fail("\"" + named + "\" is absolute; name a file relative to the suite's directory");
  for (const std::filesystem::path& part : relative)
    if (part == "..") fail("\"" + named + "\" leaves the suite's directory (\"..\"); keep the calibration beside it");
  std::filesystem::path dir = suite_file.parent_path();
  if (dir.empty()) dir = ".";
  const std::filesystem::path file = dir / relative;
  // A symlink on the way may still lead out: compare where both really are.
  std::error_code ec_dir, ec_file;
  const std::filesystem::path real_dir = std::filesystem::weakly_canonical(dir, ec_dir);
  const std::filesystem::path real_file = std::filesystem::weakly_canonical(file, ec_file);
  if (ec_dir || ec_file)
    fail("\"" + named + "\": cannot resolve the path (" + (ec_dir ? ec_dir : ec_file).message() + ")");
  if (!within(real_dir, real_file))
    fail("\"" + named + "\" resolves to " + real_file.string() + ", outside the suite's directory (a symlink)");
  return file;
}

}  // namespace tcsb
