// Checkpoint container and archive (checkpoint/): what goes in comes out bit for bit, and every
// kind of damage — a flipped byte, a cut file, another format, another case, lying lengths — is
// refused with its reason instead of being read.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>

#include "silodem/checkpoint/archive.hpp"
#include "silodem/checkpoint/checkpoint_file.hpp"
#include "silodem/core/random.hpp"

namespace fs = std::filesystem;
using namespace silodem;

namespace {

struct Sample {
  double d = 0.0;
  long l = 0;
  bool b = false;
  std::string s;
  Vec3 v = Vec3::Zero();
  std::vector<Vec3> vs;
  std::vector<bool> flags;
  std::vector<std::pair<double, std::vector<double>>> nested;
  std::optional<std::string> opt;
  void serialize(Archive& a) { a & d & l & b & s & v & vs & flags & nested & opt; }
};

Sample filled() {
  Sample x;
  x.d = std::nextafter(0.1, 1.0);  // a value text would round
  x.l = -123456789012L;
  x.b = true;
  x.s = std::string("drop\0id", 7);
  x.v = Vec3(-0.0, std::numeric_limits<double>::denorm_min(), 1e300);
  x.vs = {Vec3(1, 2, 3), Vec3(4, 5, 6)};
  x.flags = {true, false, true};
  x.nested = {{0.5, {1.0, 2.0}}, {0.25, {}}};
  x.opt = "set";
  return x;
}

std::string saved(Sample x) {
  Archive a = Archive::writer();
  a & x;
  return a.bytes();
}

fs::path scratch(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("silodem_ckpt_" + name);
  fs::remove_all(d);
  return d;
}

}  // namespace

TEST(Archive, RoundTripIsBitwise) {
  const Sample x = filled();
  Archive r = Archive::reader(saved(x));
  Sample y;
  r & y;
  r.expect_end();
  EXPECT_EQ(std::memcmp(&x.d, &y.d, sizeof x.d), 0);
  EXPECT_EQ(x.l, y.l);
  EXPECT_EQ(x.b, y.b);
  EXPECT_EQ(x.s, y.s);
  EXPECT_TRUE(std::signbit(y.v.x()));
  EXPECT_EQ(y.v.y(), std::numeric_limits<double>::denorm_min());
  EXPECT_EQ(x.vs, y.vs);
  EXPECT_EQ(x.flags, y.flags);
  EXPECT_EQ(x.nested, y.nested);
  EXPECT_EQ(x.opt, y.opt);
}

TEST(Archive, EveryTruncationIsRefused) {
  const std::string bytes = saved(filled());
  for (std::size_t n = 0; n < bytes.size(); ++n) {
    Archive r = Archive::reader(bytes.substr(0, n));
    Sample y;
    EXPECT_THROW(r & y, CheckpointError) << "cut at " << n;
  }
}

TEST(Archive, LyingCountsAndBadFlagsAreRefusedWithoutAllocating) {
  std::string bytes = saved(filled());
  // The first string's length (after d, l, b): claim 2^60 characters.
  const std::size_t at = sizeof(double) + sizeof(long) + 1;
  const std::uint64_t huge = std::uint64_t(1) << 60;
  std::memcpy(bytes.data() + at, &huge, sizeof huge);
  Archive r = Archive::reader(bytes);
  Sample y;
  EXPECT_THROW(r & y, CheckpointError);
  std::string flag = saved(filled());
  flag[sizeof(double) + sizeof(long)] = 2;  // the bool
  Archive r2 = Archive::reader(flag);
  EXPECT_THROW(r2 & y, CheckpointError);
  Archive r3 = Archive::reader(saved(filled()) + "x");
  r3 & y;
  EXPECT_THROW(r3.expect_end(), CheckpointError);
}

TEST(Archive, RandomEngineStateContinuesTheSequence) {
  Random a(42);
  for (int i = 0; i < 1000; ++i) a.uniform();
  Random b(7);
  ASSERT_TRUE(b.set_state(a.state()));
  for (int i = 0; i < 100; ++i) EXPECT_EQ(a.uniform(), b.uniform());
  EXPECT_FALSE(b.set_state("not an engine"));
}

TEST(CheckpointFile, DecodesWhatItEncodesAndRefusesDamage) {
  const std::string payload = saved(filled());
  const std::string file = encode_checkpoint(77, 1234, payload);
  long step = 0;
  EXPECT_EQ(decode_checkpoint(file, 77, &step), payload);
  EXPECT_EQ(step, 1234);
  EXPECT_EQ(decode_checkpoint(file, 0), payload);  // 0: any case
  const auto refused = [&](const std::string& bytes, std::uint64_t fp, const std::string& why) {
    try {
      decode_checkpoint(bytes, fp);
      ADD_FAILURE() << "accepted; expected: " << why;
    } catch (const CheckpointError& e) {
      EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
    }
  };
  refused(file, 78, "another case");
  for (std::size_t i = 40; i < file.size(); i += 7) {  // every 7th byte of the payload and CRC
    std::string bad = file;
    bad[i] = char(bad[i] ^ 0x10);
    refused(bad, 77, "checksum");
  }
  refused(file.substr(0, file.size() - 1), 77, "truncated");
  refused(file.substr(0, 20), 77, "not a silodem checkpoint");
  std::string version = file;
  version[8] = 9;
  refused(version, 77, "format 9");
  refused("{\"balls\": []}", 77, "not a silodem checkpoint");
}

TEST(CheckpointStore, KeepsTheNewestTwoAndFallsBackPastADamagedOne) {
  const fs::path d = scratch("store");
  const CheckpointStore store(d, 2);
  EXPECT_THROW(store.newest_valid(5), CheckpointError);  // none yet
  for (long s : {100, 200, 300}) store.save(5, s, "payload " + std::to_string(s));
  const auto files = store.files();
  ASSERT_EQ(files.size(), 2u);
  EXPECT_EQ(files[0].filename(), "step-300.ckpt");
  EXPECT_EQ(files[1].filename(), "step-200.ckpt");
  EXPECT_EQ(store.newest_valid(5).payload, "payload 300");
  // Damage the newest: the one before is used, and the refusal says why.
  { std::fstream f(files[0], std::ios::in | std::ios::out | std::ios::binary); f.seekp(42); f.put('#'); }
  const auto loaded = store.newest_valid(5);
  EXPECT_EQ(loaded.payload, "payload 200");
  EXPECT_EQ(loaded.step, 200);
  ASSERT_EQ(loaded.refused.size(), 1u);
  EXPECT_NE(loaded.refused[0].find("checksum"), std::string::npos);
  // Cut the other: nothing usable, and the message lists both.
  fs::resize_file(files[1], 30);
  try {
    store.newest_valid(5);
    ADD_FAILURE() << "a store of damaged files was accepted";
  } catch (const CheckpointError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("step-300.ckpt"), std::string::npos) << m;
    EXPECT_NE(m.find("step-200.ckpt"), std::string::npos) << m;
  }
  // A half-written temporary file (a kill during save) is not a checkpoint.
  std::ofstream(d / "step-400.ckpt.tmp") << "half";
  EXPECT_EQ(store.files().size(), 2u);
  fs::remove_all(d);
}
