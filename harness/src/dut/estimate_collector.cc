#include "hil/harness/dut/estimate_collector.h"

#include <algorithm>

#include <nlohmann/json.hpp>

#include "hil/firmware_emu/wall_time.h"

namespace hil::harness {

EstimateCollector::EstimateCollector(std::unique_ptr<EstimateReader> reader,
                                     EstimatorProcess* process, link::PtyPort* nav_pty,
                                     const std::string& raw_path, RunDiagnostics* diagnostics)
    : reader_(std::move(reader)),
      process_(process),
      nav_pty_(nav_pty),
      raw_(raw_path),
      raw_path_(raw_path),
      diagnostics_(diagnostics) {
  // JSON solutions on stdout: decoded on the process's reader thread (pty output is not its)
  if (process_ && !nav_pty_ && reader_->reads_json()) process_->set_parse_json(true);
}

void EstimateCollector::set_json_observer(JsonObserver f) {
  json_observer_ = std::move(f);
  // navd's lines scanned on the process's reader thread, where both can take the scan
  if (process_ && !nav_pty_ && reader_->reads_scanned_lines() && json_observer_.scanned)
    process_->set_scan_solutions(true);
}

void EstimateCollector::AddRecord(const EstimateRecord& r) {
  records_.push_back(r);
  ++solutions_;
  last_validity_ = r.t_validity;
}

void EstimateCollector::Keep(const std::string& line) {
  ++lines_;
  Store(line);
}

void EstimateCollector::Store(const std::string& line) {
  if (kept_bytes_ + line.size() + 1 > keep_limit_) {
    ++not_kept_;
    return;
  }
  kept_bytes_ += line.size() + 1;
  raw_ << line << "\n";  // flushed once per Poll()
  raw_unflushed_ = true;
  ++raw_lines_;
}

std::uint64_t EstimateCollector::output_bytes() const {
  return (process_ ? process_->output_bytes() : 0) + pty_bytes_;
}

void EstimateCollector::NotASolution(const std::string& line) {
  if (unparsed_++ > 0) return;
  first_unparsed_line_ = raw_lines_;
  first_unparsed_reason_ = reader_->WhyNotASolution(line);
}

void EstimateCollector::ConsumeScanned(const std::string& line, WallTime wall,
                                       const JsonSolutionLine& scan) {
  Keep(line);
  json_observer_.scanned(scan);
  if (auto r = reader_->ScannedLine(scan, wall))
    AddRecord(*r);
  else
    NotASolution(line);
}

void EstimateCollector::Consume(const std::string& line, WallTime wall,
                                const nlohmann::json* parsed) {
  Keep(line);
  std::optional<EstimateRecord> r;
  if (json_observer_.parsed && reader_->reads_json()) {
    // parsed once for both, on the process's reader thread when it could
    const nlohmann::json j =
        parsed ? nlohmann::json() : nlohmann::json::parse(line, nullptr, false);
    const nlohmann::json& doc = parsed ? *parsed : j;
    json_observer_.parsed(doc);
    r = reader_->JsonLine(doc, wall);
  } else {
    if (observer_) observer_(line);
    r = reader_->Line(line, wall);
  }
  if (r)
    AddRecord(*r);
  else if (reader_->OtherRecordOfTheStream(line))
    ++other_records_;
  else if (reader_->SolutionsInLines())
    NotASolution(line);
}

void EstimateCollector::AttachBus(std::function<std::vector<CanFrame>()> poll_bus,
                                  UnixTime start_utc) {
  poll_bus_ = std::move(poll_bus);
  bus_reader_ = std::make_unique<N2kBusReader>(start_utc);
}

std::map<std::uint32_t, std::uint64_t> EstimateCollector::bus_frames_per_pgn() const {
  return bus_reader_ ? bus_reader_->frames_per_pgn() : std::map<std::uint32_t, std::uint64_t>{};
}

void EstimateCollector::Poll() {
  Take();
  if (!raw_unflushed_) return;
  raw_unflushed_ = false;
  raw_.flush();  // everything captured so far survives an interrupted run
  if (!raw_ && diagnostics_) diagnostics_->NoteWriteFailure(raw_path_);
}

void EstimateCollector::Take() {
  if (poll_bus_) {
    const std::vector<CanFrame> frames = poll_bus_();
    const WallTime now = WallNow();
    for (const CanFrame& f : frames) {
      if (!f.extended) continue;
      bus_last_ = now;
      const std::string_view data(reinterpret_cast<const char*>(f.data.data()),
                                  std::min<std::size_t>(f.len, 8));
      if (auto r = bus_reader_->Frame(f.id, data, now)) AddRecord(*r);
    }
  }
  if (process_) {
    std::vector<OutputLine> lines = process_->TakeLines();
    for (const OutputLine& l : lines) {
      // with a pty output, stdout is only kept (diagnostics), never parsed as solutions
      if (nav_pty_) {
        Store("# stdout: " + l.text);
      } else if (l.scanned) {
        ConsumeScanned(l.text, l.wall, *l.scanned);
      } else {
        Consume(l.text, l.wall, l.json.get());
      }
    }
    process_->ReturnLines(std::move(lines));
  }
  if (nav_pty_) {
    const std::string rx = nav_pty_->ReadAvailable();
    if (!rx.empty()) {
      const WallTime now = WallNow();
      pty_last_ = now;
      pty_bytes_ += rx.size();
      pty_partial_ += rx;
      std::size_t pos;
      while ((pos = pty_partial_.find('\n')) != std::string::npos) {
        std::string line = pty_partial_.substr(0, pos);
        if (!line.empty() && line.back() == '\r') line.pop_back();
        pty_partial_.erase(0, pos + 1);
        if (!line.empty()) Consume(line, now);
      }
      if (pty_partial_.size() > EstimatorProcess::kMaxLineBytes) {  // no line: kept cut short
        Consume(pty_partial_.substr(0, EstimatorProcess::kMaxLineBytes), now);
        pty_partial_.clear();
      }
    }
  }
}

WallTime EstimateCollector::last_output_wall() const {
  const WallTime from_process = process_ && !nav_pty_ ? process_->last_output_wall() : WallTime{};
  return std::max({from_process, pty_last_, bus_last_});
}

}  // namespace hil::harness
