// hil validate: conformance of a capture, a log, a serial device or a CAN interface.
#include <cstdio>
#include <memory>

#include "hil/harness/cli/commands.h"
#include "hil/harness/validate/validate.h"
#include "hil/harness/validate/validate_can_live.h"

namespace hil::cli {
namespace {

struct ValidateArgs {
  CLI::App* cmd = nullptr;
  CLI::Option* baud_opt = nullptr;
  std::string protocol, source, report;
  int baud = 9600;
  double listen_s = 10.0;
  bool quiet = false;
};

void Declare(CLI::App& app, ValidateArgs& a) {
  a.cmd = app.add_subcommand(
      "validate",
      "Check a device's stream for conformance: framing, checksums, message set and rates "
      "against the profile, epoch timing, sequence gaps. Exit 0 conforms, 1 does not, 2 bad input");
  a.cmd
      ->add_option("--protocol", a.protocol,
                   "ubx, nmea, neo5m (NMEA and UBX against the u-blox 5 profile), mcu (MCU frame "
                   "protocol v1) or can "
                   "(candump -l log, or a live interface such as vcan0)")
      ->required()
      ->check(CLI::IsMember({"ubx", "nmea", "neo5m", "mcu", "can"}));
  a.cmd
      ->add_option("SOURCE", a.source,
                   "a hil capture (captures/*.cap), a raw log (gpsd .log), a candump -l log, or a "
                   "serial device "
                   "(e.g. /dev/ttyUSB0, RUN_DIR/ttyGPS)")
      ->required();
  a.baud_opt = a.cmd
                   ->add_option("--baud", a.baud,
                                "line rate of a serial device or a raw log: the neo5m per-epoch "
                                "byte budget (a capture's own rate, from its header, is used; "
                                "another --baud is an error)")
                   ->check(CLI::Range(300, 921600));
  a.cmd->add_option("--listen", a.listen_s, "seconds to listen to a serial device or CAN interface")
      ->check(CLI::Range(0.1, 86400.0));
  a.cmd->add_option("--report", a.report, "write the conformance report as JSON to this file");
  a.cmd->add_flag("--quiet", a.quiet, "print only the verdict line");
}

hil::harness::ValidationReport Validate(const ValidateArgs& a) {
  namespace h = hil::harness;
  if (a.protocol == "can" && h::IsNetworkInterface(a.source))
    return h::ValidateCanInterface(a.source, a.listen_s);
  const h::ByteStream s = h::ReadByteSource(a.source, a.listen_s, a.baud);
  if (a.protocol == "can") return h::ValidateCanLog(s.bytes);
  // a capture is judged at the rate it records (its timing checks: line_rate, line_budget)
  const int baud = h::ValidationBaud(s, a.baud, a.baud_opt->count() > 0);
  if (a.protocol == "mcu") return h::ValidateMcuStream(s);
  const h::ValidateProtocol p = a.protocol == "ubx"    ? h::ValidateProtocol::kUbx
                                : a.protocol == "nmea" ? h::ValidateProtocol::kNmea
                                                       : h::ValidateProtocol::kNeo5m;
  return h::ValidateStream(p, s, baud);
}

int Execute(const ValidateArgs& a) {
  hil::harness::ValidationReport rep;
  try {
    rep = Validate(a);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hil: %s\n", e.what());
    return kExitBadInput;
  }
  rep.source = a.source;
  if (a.quiet) {
    std::printf("%s: %s\n", a.source.c_str(), rep.conforms() ? "CONFORMS" : "DOES NOT CONFORM");
  } else {
    std::fputs(hil::harness::ValidationSummary(rep).c_str(), stdout);
  }
  if (!a.report.empty()) {
    try {
      hil::harness::WriteValidationJson(rep, a.report);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "hil: %s\n", e.what());
      return kExitBadInput;
    }
  }
  return rep.conforms() ? kExitPass : kExitFail;
}

}  // namespace

Subcommand AddValidate(CLI::App& app) {
  auto a = std::make_shared<ValidateArgs>();
  Declare(app, *a);
  return {a->cmd, [a] { return Execute(*a); }};
}

}  // namespace hil::cli
