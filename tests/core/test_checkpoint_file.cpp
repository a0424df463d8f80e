// The checkpoint file format (checkpoint/checkpoint_file): a round trip,
// and every kind of damage is recognised as such, never decoded as valid.
#include <cmath>
#include <cstring>
#include <damseis/checkpoint/checkpoint_file.h>
#include <damseis/input/case.h>
#include <gtest/gtest.h>
#include <limits>

using namespace damseis::checkpoint;

namespace
{
CheckpointData sample()
{
  CheckpointData d;
  d.step = 42;
  d.arrays["u"] = {1.0, -2.5, 3e-12};
  d.arrays["v"] = {};
  d.arrays["state"] = {0.25, 7.0};
  return d;
}
constexpr std::uint64_t print = 0x1234abcdu;
} // namespace

TEST(CheckpointFile, RoundTrip)
{
  const auto bytes = encode_rank(sample(), print);
  CheckpointData back;
  ASSERT_EQ(decode_rank(bytes, print, 42, back), RankFile::ok);
  EXPECT_EQ(back.step, 42);
  EXPECT_EQ(back.arrays, sample().arrays);
  const Meta m = decode_meta(encode_meta({42, 3}), "checkpoint.json");
  EXPECT_EQ(m.step, 42);
  EXPECT_EQ(m.ranks, 3);
}

TEST(CheckpointFile, AnotherModelOrStepIsAMismatch)
{
  const auto bytes = encode_rank(sample(), print);
  CheckpointData back;
  EXPECT_EQ(decode_rank(bytes, print + 1, 42, back), RankFile::mismatch);
  EXPECT_EQ(decode_rank(bytes, print, 41, back), RankFile::mismatch);
}

TEST(CheckpointFile, EveryTruncationIsRefused)
{
  const auto bytes = encode_rank(sample(), print);
  for (std::size_t n = 0; n < bytes.size(); ++n)
  {
    CheckpointData back;
    EXPECT_NE(
        decode_rank(std::string_view(bytes).substr(0, n), print, 42, back),
        RankFile::ok)
        << "truncated to " << n << " of " << bytes.size() << " bytes";
  }
}

TEST(CheckpointFile, TrailingBytesNonFiniteValuesAndHugeSizesAreDamage)
{
  const auto bytes = encode_rank(sample(), print);
  CheckpointData back;
  EXPECT_EQ(decode_rank(bytes + "x", print, 42, back), RankFile::damaged);

  // Each value of the payload in turn replaced by NaN, +inf, -inf.
  for (double bad : {std::numeric_limits<double>::quiet_NaN(),
                     std::numeric_limits<double>::infinity(),
                     -std::numeric_limits<double>::infinity()})
  {
    CheckpointData d = sample();
    d.arrays["u"][1] = bad;
    EXPECT_EQ(decode_rank(encode_rank(d, print), print, 42, back),
              RankFile::damaged);
  }

  // The array count and the first name length set to huge and negative
  // values (offsets 24 and 32 of the layout in checkpoint_file.h).
  for (std::size_t offset : {24u, 32u})
  {
    for (std::int64_t v : {std::int64_t(-1), std::int64_t(1) << 40,
                           std::numeric_limits<std::int64_t>::max()})
    {
      std::string damaged = bytes;
      std::memcpy(damaged.data() + offset, &v, sizeof v);
      EXPECT_EQ(decode_rank(damaged, print, 42, back), RankFile::damaged)
          << "offset " << offset << " value " << v;
    }
  }
}

TEST(CheckpointFile, DamagedMetaIsOneLineNamingTheFile)
{
  for (const char* text :
       {"", "{", "[1, 2]", "{\"step\": \"2\", \"ranks\": 1}", "{\"step\": 2}",
        "{\"step\": -1, \"ranks\": 1}", "{\"step\": 1e3, \"ranks\": 1}",
        "{\"step\": 2, \"ranks\": 0}", "{\"step\": 99999999999, \"ranks\": 1}",
        "null", "\x01\x02"})
  {
    try
    {
      decode_meta(text, "out/checkpoint/checkpoint.json");
      ADD_FAILURE() << "accepted: " << text;
    }
    catch (const damseis::input::InputError& e)
    {
      const std::string what = e.what();
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
      EXPECT_EQ(what.rfind("out/checkpoint/checkpoint.json: damaged", 0), 0u)
          << what;
    }
  }
}

TEST(CheckpointFile, CaseFingerprintIgnoresRunOutputSolverAndComments)
{
  const std::string a = "[material]\nE = 3e10  # Pa\n[run]\nrestart = false\n";
  const std::string b = "# header\n[material]\nE = 3e10  # modulus\n[run]\n"
                        "restart = true\n[output]\nfolder = \"x\"\n";
  const std::string c = "[material]\nE = 3.1e10  # Pa\n";
  EXPECT_EQ(case_fingerprint(a), case_fingerprint(b));
  EXPECT_NE(case_fingerprint(a), case_fingerprint(c));
  // A default key is a commented line (Case::to_toml) whose value counts.
  const std::string d = "[material]\n# E = 3e10  # Pa (default)\n";
  const std::string e = "[material]\n# E = 3.1e10  # Pa (default)\n";
  EXPECT_NE(case_fingerprint(d), case_fingerprint(e));
  EXPECT_NE(case_fingerprint(d), case_fingerprint("[material]\n"));
}
