#include "hil/harness/campaign/campaign_folder.h"

#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace hil::harness {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::optional<json> ReadJson(const std::string& path) {
  std::ifstream in(path);
  if (!in) return std::nullopt;
  json j = json::parse(in, nullptr, false);
  if (j.is_discarded()) return std::nullopt;
  return j;
}

}  // namespace

void WriteFileAtomically(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".tmp." + std::to_string(getpid());
  const int fd = open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw std::runtime_error("cannot write " + tmp);
  std::size_t off = 0;
  while (off < text.size()) {
    const ssize_t n = write(fd, text.data() + off, text.size() - off);
    if (n <= 0) {
      close(fd);
      unlink(tmp.c_str());
      throw std::runtime_error("cannot write " + tmp);
    }
    off += static_cast<std::size_t>(n);
  }
  const bool synced = fsync(fd) == 0;
  close(fd);
  if (!synced || std::rename(tmp.c_str(), path.c_str()) != 0) {
    unlink(tmp.c_str());
    throw std::runtime_error("cannot rename " + tmp + " to " + path);
  }
}

CampaignFolder PrepareCampaignFolder(const std::string& dir, const CampaignPlan& plan, int shards) {
  std::error_code ec;
  for (const char* sub : {"records", "runs", "shards", "logs"})
    fs::create_directories(fs::path(dir) / sub, ec);
  if (ec || access(dir.c_str(), W_OK) != 0)
    throw CampaignFolderError("cannot write the campaign folder " + dir);
  const std::string path = dir + "/campaign.json";
  const json plan_json = PlanToJson(plan);
  if (const auto old = ReadJson(path)) {
    if (old->value("plan", json()) != plan_json)
      throw CampaignFolderError(dir + " holds another campaign (" + path +
                                " differs from this one's plan): use another --out folder");
    const int old_shards = old->value("shards", 1);
    if (shards > 0 && shards != old_shards)
      throw CampaignFolderError(dir + " was planned for " + std::to_string(old_shards) +
                                " shard(s), not " + std::to_string(shards));
    return {dir, plan, old_shards, old->value("workdir", "")};
  }
  CampaignFolder f{dir, plan, shards > 0 ? shards : 1, fs::current_path().string()};
  const json j{{"format", "hil-campaign-1"},
               {"plan", plan_json},
               {"shards", f.shards},
               {"runs", plan.runs.size()},
               {"workdir", f.workdir}};
  WriteFileAtomically(path, j.dump(2) + "\n");
  return f;
}

CampaignFolder LoadCampaignFolder(const std::string& dir) {
  const std::string path = dir + "/campaign.json";
  const auto j = ReadJson(path);
  if (!j) throw CampaignFolderError("not a campaign folder: cannot read " + path);
  try {
    return {dir, PlanFromJson(j->at("plan")), j->value("shards", 1), j->value("workdir", "")};
  } catch (const std::exception& e) {
    throw CampaignFolderError(path + ": " + e.what());
  }
}

std::string RecordPath(const std::string& dir, const CampaignRun& run) {
  return dir + "/records/" + run.id + ".json";
}

std::optional<json> ReadRecord(const std::string& dir, const CampaignRun& run) {
  auto j = ReadJson(RecordPath(dir, run));
  if (!j || !j->is_object() || !j->contains("run") || (*j)["run"].value("id", "") != run.id)
    return std::nullopt;
  return j;
}

std::string ShardStatePath(const std::string& dir, int shard) {
  return dir + "/shards/shard-" + std::to_string(shard) + ".json";
}

}  // namespace hil::harness
