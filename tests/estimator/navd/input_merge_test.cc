// navd's input merge (input_merge.h): the filter gets the same sequence of inputs whatever the
// interleaving of the links' reads, within the window; counters travel with their items.
#include "hil/estimator/navd/input_merge.h"

#include <chrono>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace hil::estimator {
namespace {

GpsTime T(double s) {
  return GpsTime{} + std::chrono::duration_cast<Nanoseconds>(std::chrono::duration<double>(s));
}

MergeItem Imu(double t_s) {
  MergeItem m;
  m.kind = MergeItem::Kind::kImu;
  m.t = T(t_s);
  ImuSample s;
  s.t = m.t;
  m.imu = s;
  m.from_mcu = true;
  m.mcu.frames_ok = static_cast<std::uint64_t>(t_s * 100);
  return m;
}

MergeItem Gnss(double t_s, std::uint64_t garbage) {
  MergeItem m;
  m.kind = MergeItem::Kind::kGnss;
  m.t = T(t_s);
  m.gnss.t = m.t;
  m.nmea.garbage_bytes = garbage;
  return m;
}

// What the filter would see, as "I<t>" and "G<t>", with the GNSS counters at each release.
struct Seen {
  std::vector<std::string> order;
  std::vector<std::uint64_t> gnss_garbage;
};

Seen Merged(const std::vector<MergeItem>& reads, Nanoseconds window) {
  Seen seen;
  InputMerge* self = nullptr;
  InputMerge merge(window, 64, [&](const MergeItem& m) {
    const double t = std::chrono::duration<double>(m.t.time_since_epoch()).count();
    seen.order.push_back((m.kind == MergeItem::Kind::kImu ? "I" : "G") + std::to_string(t));
    seen.gnss_garbage.push_back(self->counters().nmea.garbage_bytes);
  });
  self = &merge;
  for (const MergeItem& m : reads) merge.Add(m);
  merge.ReleaseAll();
  return seen;
}

TEST(InputMergeTest, TwoInterleavingsOfTheLinksGiveOneSequenceInDeviceTimeOrder) {
  // IMU at 100 Hz, GNSS at 10 Hz (a fix's bytes decoded 30 ms after its time of validity)
  std::vector<MergeItem> imu, gnss;
  for (int k = 0; k <= 300; ++k) imu.push_back(Imu(0.01 * k));
  for (int k = 0; k <= 30; ++k) gnss.push_back(Gnss(0.1 * k, static_cast<std::uint64_t>(k)));
  // reads as they happen message by message ...
  std::vector<MergeItem> fine;
  std::size_t g = 0;
  for (const MergeItem& i : imu) {
    while (g < gnss.size() && gnss[g].t + std::chrono::milliseconds(30) <= i.t)
      fine.push_back(gnss[g++]);
    fine.push_back(i);
  }
  while (g < gnss.size()) fine.push_back(gnss[g++]);
  // ... and in batches: 50 IMU samples (0.5 s), then the GNSS epochs of up to 0.5 s ahead
  std::vector<MergeItem> batched;
  g = 0;
  for (std::size_t k = 0; k < imu.size(); k += 50) {
    for (std::size_t j = k; j < std::min(imu.size(), k + 50); ++j) batched.push_back(imu[j]);
    while (g < gnss.size() && gnss[g].t <= imu[std::min(imu.size() - 1, k + 99)].t)
      batched.push_back(gnss[g++]);
  }
  while (g < gnss.size()) batched.push_back(gnss[g++]);

  const Seen a = Merged(fine, std::chrono::seconds(1));
  const Seen b = Merged(batched, std::chrono::seconds(1));
  EXPECT_EQ(a.order, b.order);
  EXPECT_EQ(a.gnss_garbage, b.gnss_garbage);
  ASSERT_EQ(a.order.size(), imu.size() + gnss.size());
  // device-time order, IMU first at one time
  EXPECT_EQ(a.order[0], "I" + std::to_string(0.0));
  EXPECT_EQ(a.order[1], "G" + std::to_string(0.0));
  // off: as read, so the two interleavings differ
  EXPECT_NE(Merged(fine, Nanoseconds{0}).order, Merged(batched, Nanoseconds{0}).order);
}

TEST(InputMergeTest, HoldsUntilTheImuIsAWindowPastAndReleasesAnItemOlderThanThatAtOnce) {
  std::vector<std::string> seen;
  InputMerge merge(std::chrono::seconds(1), 64, [&](const MergeItem& m) {
    seen.push_back(m.kind == MergeItem::Kind::kImu ? "I" : "G");
  });
  merge.Add(Imu(0.0));
  merge.Add(Gnss(0.5, 0));
  merge.Add(Imu(0.9));
  EXPECT_TRUE(seen.empty());
  EXPECT_EQ(merge.held(), 3u);
  merge.Add(Imu(1.5));  // 1.5 - 1 = 0.5: the IMU at 0 and the fix at 0.5 go
  EXPECT_EQ(seen, (std::vector<std::string>{"I", "G"}));
  merge.Add(Gnss(0.2, 0));  // older than what went on: at once
  EXPECT_EQ(seen.back(), "G");
  // no IMU any more: the fixes go twice the window behind the newest one
  merge.Add(Gnss(3.0, 0));
  merge.Add(Gnss(3.6, 0));
  EXPECT_EQ(merge.held(), 2u) << "the fixes at 3.0 and 3.6: everything up to 3.6 s - 2 s went on";
}

}  // namespace
}  // namespace hil::estimator
