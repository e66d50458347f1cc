#include "hil/harness/run/run_folder.h"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include "hil/harness/run/folder_lock.h"

namespace hil::harness {
namespace {

namespace fs = std::filesystem;

bool SameFolder(const fs::path& a, const char* b) {
  if (b == nullptr || *b == '\0') return false;
  std::error_code ec;
  return fs::equivalent(a, b, ec) && !ec;
}

}  // namespace

std::optional<std::string> WhyNotARunFolder(const std::string& out_dir) {
  if (out_dir.empty()) return "an empty folder name";
  std::error_code ec;
  const fs::file_status st = fs::status(out_dir, ec);
  if (ec || !fs::exists(st)) return std::nullopt;  // made by the run
  if (!fs::is_directory(st)) return std::nullopt;  // creating it fails with the reason
  const fs::path dir(out_dir);
  if (SameFolder(dir, "/"))
    return "is the root folder: a run writes report.json, captures/... into its folder";
  if (SameFolder(dir, std::getenv("HOME")))
    return "is the home folder: a run writes report.json, captures/... into its folder";
  if (fs::exists(dir / "report.json", ec) || fs::exists(dir / kRunLockName, ec))
    return std::nullopt;  // a previous run's folder: run again into it
  if (fs::is_empty(dir, ec) && !ec) return std::nullopt;
  return "exists and is neither empty nor a previous run's folder (no report.json or " +
         std::string(kRunLockName) +
         "): a run would overwrite files of the same names in it; give a new or empty folder";
}

void MakeRunFolder(const std::string& out_dir) {
  if (const auto why = WhyNotARunFolder(out_dir))
    throw std::runtime_error("refusing the output folder " + out_dir + ": " + *why);
  std::error_code ec;
  fs::create_directories(out_dir, ec);
  if (ec || access(out_dir.c_str(), W_OK) != 0) {
    throw std::runtime_error("cannot write the output folder " + out_dir +
                             (ec ? ": " + ec.message() : ""));
  }
}

}  // namespace hil::harness
