// The declared options (sim/app/options.hpp): one list per verb, the command line's
// options and help made from it (sim/cli/declared_options.hpp), its values checked once,
// at the bound and one past it. A verb declared here, in the test, needs only its
// options struct and one registry line to get both.
#include <CLI/CLI.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "sim/app/verbs.hpp"
#include "sim/cli/declared_options.hpp"
#include "sim/core/errors.hpp"
#include "support/cli.hpp"

namespace mmv::app {
namespace {

/// A new verb: every kind of field once.
struct DemoParams {
  int count = 3;
  double tolerance = 0;
  double spacing = 0.5;
  bool estimate = true;
  bool loud = false;
  std::string method = "fast";
  std::vector<std::string> points;
  std::vector<std::string> spans;
  Band band{1, 10};
  std::optional<double> duration;  // absent: the scene's

  template <class S, class V>
  static void fields(S& s, V&& v) {
    v(s.count, Option("count", "Things counted").range(1, 100));
    v(s.tolerance, Option("tolerance", "Tolerance met").range(1e-9, 0.5).off(0));
    v(s.spacing, Option("spacing", "Spacing between things").unit("m").above(0, 10));
    v(s.estimate, Option("estimate", "Estimate the error").negated("--no-estimate", "Skip the error estimate"));
    v(s.loud, Option("loud", "Say more"));
    v(s.method, Option("method", "How").choices("fast,slow"));
    v(s.points, Option("points", "Points shown").commaSeparated());
    v(s.spans, Option("spans", "Spans shown").flag("--span"));
    v(s.band, Option("band_hz", "Band of interest").unit("Hz").flag("--band"));
    v(s.duration, Option("duration", "Seconds run").unit("s").above(0).below(100).whenAbsent("the scene's"));
  }
};

const VerbDeclaration kDemo = declareVerb<DemoParams>("demo", "A verb declared in a test", "demo.csv");  // its registry line

/// The demo verb's command line parsed into its options.
DemoParams parsed(std::vector<std::string> args) {
  CLI::App app;
  DemoParams p;
  mmv::cli::addDeclaredOptions(&app, p);
  args.insert(args.begin(), "demo");
  std::vector<const char*> argv;
  for (const auto& a : args) argv.push_back(a.c_str());
  app.parse(static_cast<int>(argv.size()), argv.data());
  return p;
}

TEST(DeclaredOptions, TheCommandLineIsMadeFromTheDeclaration) {
  const DemoParams p = parsed({"--count", "7", "--tolerance", "1e-3", "--no-estimate", "--loud", "--method", "slow",
                               "--points", "a,b", "--span", "x:y", "--span", "z:w", "--band", "2:20", "--spacing", "0.25"});
  EXPECT_EQ(p.count, 7);
  EXPECT_EQ(p.tolerance, 1e-3);
  EXPECT_FALSE(p.estimate);
  EXPECT_TRUE(p.loud);
  EXPECT_EQ(p.method, "slow");
  EXPECT_EQ(p.points, (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(p.spans, (std::vector<std::string>{"x:y", "z:w"}));
  EXPECT_EQ(p.band, (Band{2, 20}));
  EXPECT_EQ(p.spacing, 0.25);
  EXPECT_FALSE(p.duration.has_value());  // not given: absent, whatever a number's default
  EXPECT_EQ(parsed({"--duration", "0"}).duration, 0.0);  // given, even 0: for the study to refuse
  const DemoParams d = parsed({});  // nothing given: the declaration's defaults
  EXPECT_EQ(d.count, 3);
  EXPECT_TRUE(d.estimate);
  EXPECT_EQ(d.band, (Band{1, 10}));
  EXPECT_THROW(parsed({"--band", "2"}), CLI::ValidationError);
  EXPECT_THROW(parsed({"--band", "a:b"}), CLI::ValidationError);
  EXPECT_THROW(parsed({"--span", "x:y", "z:w"}), CLI::ParseError);  // one item per --span
}

TEST(DeclaredOptions, HelpShowsWhatTheDescriptionSays) {
  CLI::App app;
  DemoParams p;
  mmv::cli::addDeclaredOptions(&app, p);
  const std::string help = app.help();
  const std::vector<OptionDescription> described = kDemo.options();
  ASSERT_EQ(described.size(), 10u);
  for (const auto& d : described) {
    if (d.type == "bool") continue;  // a flag: its own sentence, no default
    EXPECT_NE(help.find(d.help_text), std::string::npos) << d.option.key() << ": " << d.help_text << "\n" << help;
  }
  EXPECT_NE(help.find("Skip the error estimate"), std::string::npos);
  // The text both fronts show, from the declaration alone.
  EXPECT_EQ(described[0].help_text, "Things counted [1 .. 100; default 3]");
  EXPECT_EQ(described[1].help_text, "Tolerance met [0 (off) or 1e-09 .. 0.5; default 0 (off)]");
  EXPECT_EQ(described[2].help_text, "Spacing between things [m; above 0, at most 10; default 0.5]");
  EXPECT_EQ(described[5].help_text, "How [one of fast, slow; default fast]");
  EXPECT_EQ(described[8].help_text, "Band of interest [Hz; default 1:10]");
  EXPECT_EQ(described[8].default_value, nlohmann::json::array({1.0, 10.0}));
  EXPECT_EQ(described[9].help_text, "Seconds run [s; above 0, below 100; default the scene's]");
  EXPECT_TRUE(described[9].default_value.is_null());
  EXPECT_EQ(described[9].type, "float?");
  EXPECT_EQ(described[6].option.cliFlag(), "--points");
  EXPECT_EQ(described[7].option.cliFlag(), "--span");
}

/// A UsageError's message from `checkOptions`, "" for none.
std::string refusal(const DemoParams& p, Front front = Front::Cli) {
  try {
    checkOptions(p, front);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

TEST(DeclaredOptions, EveryRangeHoldsAtItsBoundAndRefusesOnePast) {
  DemoParams p;
  EXPECT_EQ(refusal(p), "");
  p.count = 1;
  EXPECT_EQ(refusal(p), "");
  p.count = 0;
  EXPECT_EQ(refusal(p), "--count: must be a finite number of at least 1 and at most 100 (got 0)");
  EXPECT_EQ(refusal(p, Front::Python), "count: must be a finite number of at least 1 and at most 100 (got 0)");
  p.count = 100;
  EXPECT_EQ(refusal(p), "");
  p.count = 101;
  EXPECT_NE(refusal(p), "");
  p.count = 3;
  for (double t : {0.0, 1e-9, 0.5}) {
    p.tolerance = t;
    EXPECT_EQ(refusal(p), "") << t;
  }
  for (double t : std::vector<double>{-1e-300, 0.5 * 1e-9, std::nextafter(0.5, 1.0), std::nan(""), HUGE_VAL}) {
    p.tolerance = t;
    EXPECT_NE(refusal(p).find("--tolerance: must be 0 (off) or a finite number of at least 1e-09"), std::string::npos) << t;
  }
  p.tolerance = 0;
  p.spacing = 0;  // above 0: the bound itself is out
  EXPECT_NE(refusal(p).find("--spacing: must be a finite number above 0 and at most 10"), std::string::npos);
  p.spacing = 10;
  EXPECT_EQ(refusal(p), "");
  p.spacing = std::nextafter(10.0, 11.0);
  EXPECT_NE(refusal(p), "");
  p.spacing = 1;
  p.method = "slwo";
  EXPECT_EQ(refusal(p), "--method: unknown value 'slwo' (did you mean 'slow'?) (known: fast, slow)");
  p.method = "slow";
  p.band = {5, 5};
  EXPECT_EQ(refusal(p), "--band: expected 0 <= F_MIN_HZ < F_MAX_HZ (got 5:5)");
  EXPECT_EQ(refusal(p, Front::Python), "band_hz: expected 0 <= F_MIN_HZ < F_MAX_HZ (got 5:5)");
  p.band = {0, 5};
  EXPECT_EQ(refusal(p), "");
  p.duration = 0;  // given as 0: refused, not read as absent
  EXPECT_EQ(refusal(p), "--duration: must be a finite number above 0 and below 100 (got 0)");
  p.duration = std::nextafter(100.0, 0.0);
  EXPECT_EQ(refusal(p), "");
  p.duration = 100;  // below 100: the bound itself is out
  EXPECT_NE(refusal(p), "");
  p.duration.reset();
  EXPECT_EQ(refusal(p), "");
  EXPECT_EQ(declaredName<DemoParams>("spans", Front::Cli), "--span");
  EXPECT_EQ(declaredName<DemoParams>("spans", Front::Python), "spans");
  EXPECT_THROW(declaredName<DemoParams>("nothing", Front::Cli), std::logic_error);
}

}  // namespace
}  // namespace mmv::app

namespace mmv::cli_testing {
namespace {

// Every registered verb's --help, as the executable prints it, holds each declared
// option's flag with the declaration's text (help, unit, range, default); Python's side
// of the same list is python/tests/test_declared.py.
TEST_F(Cli, EveryDeclaredVerbsHelpIsItsDeclaration) {
  ASSERT_GE(app::declaredVerbs().size(), 5u);
  for (const auto& verb : app::declaredVerbs()) {
    const Result r = run(verb.name + " --help");
    ASSERT_EQ(r.code, 0) << verb.name << r.err;
    EXPECT_EQ(r.out.rfind(verb.summary, 0), 0u) << verb.name << "\n" << r.out;
    for (const auto& d : verb.options()) {
      const std::size_t at = r.out.find("  " + d.option.cliFlag() + " ");
      ASSERT_NE(at, std::string::npos) << verb.name << " " << d.option.cliFlag() << "\n" << r.out;
      const std::string line = r.out.substr(at, r.out.find("\n  -", at + 1) - at);
      const std::string text = d.type == "bool" ? (d.option.negatedFlag() ? d.option.negatedHelp() : d.option.helpText(""))
                                                : d.help_text;
      EXPECT_NE(line.find(text), std::string::npos) << verb.name << ": " << text << "\nin: " << line;
    }
  }
}

}  // namespace
}  // namespace mmv::cli_testing
