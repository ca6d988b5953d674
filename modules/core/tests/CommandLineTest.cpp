#include <dynslam/core/CommandLine.h>

#include <gtest/gtest.h>

using dynslam::core::CommandLine;
using dynslam::core::UsageError;

namespace {
CommandLine parse(std::vector<const char*> args) {
  args.insert(args.begin(), "prog");
  CommandLine cl({"--in", "--n"}, {"--fast"}, {"--set"}, 2);
  cl.parse(static_cast<int>(args.size()), args.data());
  return cl;
}
}  // namespace

TEST(CommandLine, FlagsSwitchesRepeatsAndPositionals) {
  const auto cl =
      parse({"ape", "--in", "a.txt", "--set", "x.y=1", "--fast", "--set", "x.z=2", "b"});
  EXPECT_EQ(cl.required("--in"), "a.txt");
  EXPECT_TRUE(cl.has("--fast"));
  EXPECT_EQ(cl.all("--set"), (std::vector<std::string>{"x.y=1", "x.z=2"}));
  EXPECT_EQ(cl.positional(), (std::vector<std::string>{"ape", "b"}));
  EXPECT_EQ(cl.valueOr("--n", "7"), "7");
  EXPECT_FALSE(cl.optionalInteger("--n").has_value());
}

TEST(CommandLine, BadInputIsAUsageErrorNamingTheFlag) {
  const auto expectError = [](std::vector<const char*> args, const std::string& word) {
    try {
      parse(std::move(args));
      FAIL() << "no error; expected one naming " << word;
    } catch (const UsageError& e) {
      EXPECT_NE(std::string(e.what()).find(word), std::string::npos) << e.what();
    }
  };
  expectError({"--bogus"}, "--bogus");
  expectError({"--in"}, "--in");
  expectError({"--in", "a", "--in", "b"}, "--in");
  expectError({"a", "b", "c"}, "'c'");
  EXPECT_THROW(parse({"--n", "3x"}).optionalInteger("--n"), UsageError);
  EXPECT_THROW(parse({}).required("--in"), UsageError);
}

TEST(CommandLine, AnMrptExceptionReachesTheUserAsItsMessageLine) {
  const std::string mrpt =
      "==== MRPT exception ====\n"
      "Message:  Cannot open 'x.png'\n"
      "Location: mrpt::img::CImage::loadFromFile\n"
      "Call stack backtrace:\n[0x1] main\n";
  EXPECT_EQ(dynslam::core::userMessage(mrpt), "Cannot open 'x.png'");
  const std::string ours = "[Estimator] window_size of a.ini: must be >= 2\n(read: 1)";
  EXPECT_EQ(dynslam::core::userMessage(ours), ours) << "other messages unchanged";
  // runProgram prints the same.
  testing::internal::CaptureStderr();
  const int code =
      dynslam::core::runProgram("prog", [&]() -> int { throw std::runtime_error(mrpt); });
  EXPECT_EQ(code, 1);
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "prog: error: Cannot open 'x.png'\n");
}
