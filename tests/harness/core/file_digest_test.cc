// SHA-256 of the scenario file for report.html's header: FIPS 180-2's test vectors, and a file's
// digest is that of its bytes.
#include "hil/harness/core/file_digest.h"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

namespace hil::harness {
namespace {

TEST(FileDigestTest, Fips180Vectors) {
  EXPECT_EQ(Sha256Hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(Sha256Hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(Sha256Hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
}

TEST(FileDigestTest, FileDigestIsItsBytesDigest) {
  const std::filesystem::path p =
      std::filesystem::temp_directory_path() / ("digest_" + std::to_string(::getpid()) + ".yaml");
  const std::string bytes = std::string("name: x\n\0binary\xff", 16);
  std::ofstream(p, std::ios::binary) << bytes;
  EXPECT_EQ(Sha256OfFile(p.string()), Sha256Hex(bytes));
  std::filesystem::remove(p);
  EXPECT_FALSE(Sha256OfFile(p.string()));
}

}  // namespace
}  // namespace hil::harness
