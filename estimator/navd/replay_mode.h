#pragma once
/// @file
/// `navd --replay LOG... --out DIR [--navd-conf FILE]`: a recorded device log fed to navd's own
/// decoders and filter in virtual time (the data's own time tags drive the filter; nothing is
/// paced): hil captures (`RUN/captures/*.cap`, every link merged by its recorded byte times: MCU
/// frames to the IMU decoder, NMEA/UBX to the GNSS receiver) or a raw receiver log (u-blox UBX or
/// NMEA bytes, e.g. gpsd's regression logs, read in place; leading '#' lines skipped). The
/// solutions go to KF-GINS's result files in DIR; the consistency report (no truth: rates, gaps,
/// NIS, fix-to- fix innovations) to stdout and DIR/replay_report.txt. Score against a reference
/// trajectory with `hil dataset score REFERENCE.nav DIR/KF_GINS_Navresult.nav`.

namespace hil::navd {

bool WantsReplayMode(int argc, char** argv);
int ReplayMain(int argc, char** argv);

}  // namespace hil::navd
