/// Tests of damseis/case: schema, case files, --set overrides, command line.
#include <damseis/input/case.h>
#include <damseis/input/command_line.h>

#include <atomic>
#include <fstream>
#include <functional>
#include <gtest/gtest.h>
#include <initializer_list>
#include <string>
#include <unistd.h>
#include <vector>

namespace fs = std::filesystem;
using namespace damseis::input;

namespace
{

const fs::path data_dir = fs::path(DAMSEIS_TEST_DATA) / "case";

/// The schema used by the tests (shaped like a demo's).
Schema make_schema()
{
  Schema schema;
  schema.string("title", "\"\"", "-", "Title of the case");
  schema.real("material.E", "30e9", "Pa", "Young's modulus").above(0);
  schema.real("material.nu", "0.2", "-", "Poisson's ratio")
      .between_exclusive(-1, 0.5);
  schema.real("material.rho", "2643", "kg/m^3", "Mass density").above(0);
  schema.integer("mesh.order", "2", "-", "Polynomial degree").between(1, 2);
  schema.string("mesh.file", "\"\"", "-", "Mesh file (empty: generate)");
  schema.boolean("mesh.refine", "false", "-", "Refine near the heel");
  schema.real("time.dt", "0.01", "s", "Time step").above(0);
  schema.integer_array("damping.modes", "[1, 3]", "-", "Rayleigh modes")
      .at_least(1);
  schema.real_array("damping.ratios", "[0.05, 0.05]", "-", "Damping ratios")
      .between(0, 1);
  schema.string_array("output.groups", "[\"dam\", \"rock\"]", "-",
                      "Mesh groups to report");
  schema.string("output.stress", "seismic", "-", "Stress to save",
                {"static", "seismic", "total"});
  schema.integer("output.vtk.every", "10", "-", "VTK output every n steps")
      .at_least(1);
  return schema;
}

/// A fresh directory for the files of one test, removed at the end.
class TempDir
{
public:
  TempDir()
  {
    static std::atomic<int> counter{0};
    const auto* info = testing::UnitTest::GetInstance()->current_test_info();
    path_ = fs::path(testing::TempDir()) /
            ("damseis_case_" + std::string(info->name()) + "_" +
             std::to_string(::getpid()) + "_" + std::to_string(counter++));
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempDir() { fs::remove_all(path_); }
  fs::path write(const std::string& name, const std::string& content) const
  {
    const fs::path file = path_ / name;
    std::ofstream(file, std::ios::binary) << content;
    return file;
  }
  const fs::path& path() const { return path_; }

private:
  fs::path path_;
};

/// Expects `f` to throw InputError with a one-line message containing all of
/// `parts`; returns the message.
std::string expect_input_error(const std::function<void()>& f,
                               std::initializer_list<std::string> parts)
{
  try
  {
    f();
  }
  catch (const InputError& e)
  {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_EQ(message.find('\r'), std::string::npos) << message;
    for (const auto& part : parts)
      EXPECT_NE(message.find(part), std::string::npos)
          << "missing \"" << part << "\" in: " << message;
    return message;
  }
  ADD_FAILURE() << "no InputError thrown";
  return {};
}

/// Loads `content` written to "<name>" in a temporary directory.
Case load_text(const std::string& content,
               const std::vector<std::string>& overrides = {},
               const std::string& name = "case.toml")
{
  TempDir dir;
  return Case::load(make_schema(), dir.write(name, content), overrides);
}

/// Expects loading `content` (with `overrides`) to fail with a one-line
/// message containing the file name and all of `parts`.
std::string expect_load_error(const std::string& content,
                              std::initializer_list<std::string> parts,
                              const std::vector<std::string>& overrides = {})
{
  std::string message = expect_input_error(
      [&] { load_text(content, overrides, "bad_case.toml"); }, parts);
  EXPECT_NE(message.find("bad_case.toml"), std::string::npos) << message;
  return message;
}

} // namespace

// ---------------------------------------------------------------------------
// Schema
// ---------------------------------------------------------------------------

TEST(CaseSchema, HelpTextListsKeysUnitsDefaultsConstraints)
{
  const std::string help = make_schema().help_text();
  for (const std::string part :
       {"[material]", "[output.vtk]", "material.E", "real", "Pa", "3e+10",
        "Young's modulus", "[E > 0]", "[-1 < nu < 0.5]", "[1 <= order <= 2]",
        "[modes[i] >= 1]", "int[]", "\"seismic\"",
        "one of \"static\", \"seismic\", \"total\"", "(top level)", "title"})
    EXPECT_NE(help.find(part), std::string::npos) << part << "\n" << help;
  // Top-level keys are listed first.
  EXPECT_LT(help.find("(top level)"), help.find("[material]"));
}

TEST(CaseSchema, ConstraintText)
{
  Schema schema;
  EXPECT_EQ(schema.real("a.x", "1", "m", "").above(0).key().constraint_text(),
            "x > 0");
  EXPECT_EQ(schema.real("a.y", "1", "m", "").at_most(2).key().constraint_text(),
            "y <= 2");
  EXPECT_EQ(schema.real("a.z", "0", "m", "").below(0.5).key().constraint_text(),
            "z < 0.5");
  EXPECT_EQ(
      schema.real("a.w", "1", "m", "").at_least(-1).key().constraint_text(),
      "w >= -1");
  EXPECT_EQ(schema.real("a.u", "1", "m", "").key().constraint_text(), "");
}

TEST(CaseSchema, BadDeclarationsAreLogicErrors)
{
  Schema schema = make_schema();
  EXPECT_THROW(schema.real("material.E", "1", "Pa", ""), std::logic_error);
  EXPECT_THROW(schema.real("material", "1", "-", ""), std::logic_error);
  EXPECT_THROW(schema.real("material.E.x", "1", "-", ""), std::logic_error);
  EXPECT_THROW(schema.real("bad key", "1", "-", ""), std::logic_error);
  EXPECT_THROW(schema.real("a..b", "1", "-", ""), std::logic_error);
  EXPECT_THROW(schema.real("a.b", "abc", "-", ""), std::logic_error);
  EXPECT_THROW(schema.integer("a.c", "1.5", "-", ""), std::logic_error);
  EXPECT_THROW(schema.boolean("a.d", "1", "-", ""), std::logic_error);
  EXPECT_THROW(schema.integer_array("a.e", "[1.5]", "-", ""), std::logic_error);
  EXPECT_THROW(schema.string("a.f", "\"x\"", "-", "").above(0),
               std::logic_error);
  EXPECT_THROW(schema.boolean("a.g", "true", "-", "").at_most(1),
               std::logic_error);
  EXPECT_NO_THROW(schema.string("a.h", "bare_word", "-", ""));
}

TEST(CaseSchema, DefaultOutsideBoundsIsLogicErrorAtLoad)
{
  TempDir dir;
  const fs::path file = dir.write("empty.toml", "");
  {
    Schema schema;
    schema.real("a.x", "0", "-", "").above(0); // exclusive bound
    EXPECT_THROW(Case::load(schema, file), std::logic_error);
  }
  {
    Schema schema;
    schema.string("a.s", "\"x\"", "-", "", {"y", "z"});
    EXPECT_THROW(Case::load(schema, file), std::logic_error);
  }
  {
    Schema schema;
    schema.integer_array("a.v", "[1, 0]", "-", "").at_least(1);
    EXPECT_THROW(Case::load(schema, file), std::logic_error);
  }
  {
    Schema schema;
    schema.real("a.x", "0", "-", "").at_least(0); // inclusive bound: fine
    EXPECT_NO_THROW(Case::load(schema, file));
  }
}

// ---------------------------------------------------------------------------
// Loading
// ---------------------------------------------------------------------------

TEST(CaseLoad, Defaults)
{
  const Case c = load_text("# nothing\n[material]\n");
  EXPECT_EQ(c.string("title"), "");
  EXPECT_DOUBLE_EQ(c.real("material.E"), 30e9);
  EXPECT_DOUBLE_EQ(c.real("material.nu"), 0.2);
  EXPECT_DOUBLE_EQ(c.real("material.rho"), 2643.0); // integer default
  EXPECT_EQ(c.integer("mesh.order"), 2);
  EXPECT_FALSE(c.boolean("mesh.refine"));
  EXPECT_EQ(c.integers("damping.modes"), (std::vector<std::int64_t>{1, 3}));
  EXPECT_EQ(c.reals("damping.ratios"), (std::vector<double>{0.05, 0.05}));
  EXPECT_EQ(c.string("output.stress"), "seismic"); // bare default
  EXPECT_EQ(c.integer("output.vtk.every"), 10);
  const Schema schema = make_schema();
  for (const Key& key : schema.keys())
    EXPECT_FALSE(c.is_set(key.path)) << key.path;
}

TEST(CaseLoad, FileValues)
{
  const fs::path file = data_dir / "dam.toml";
  const Case c = Case::load(make_schema(), file);
  EXPECT_EQ(c.file(), file);
  EXPECT_EQ(c.string("title"), "Koyna test");
  EXPECT_DOUBLE_EQ(c.real("material.E"), 31.027e9);
  EXPECT_DOUBLE_EQ(c.real("time.dt"), 1.0); // integer literal for a real
  EXPECT_EQ(c.integer("mesh.order"), 1);
  EXPECT_EQ(c.string("output.stress"), "total");
  EXPECT_EQ(c.integer("output.vtk.every"), 5);
  EXPECT_TRUE(c.is_set("material.E"));
  EXPECT_TRUE(c.is_set("time.dt"));
  EXPECT_TRUE(c.is_set("output.vtk.every"));
  EXPECT_FALSE(c.is_set("material.rho"));
  EXPECT_DOUBLE_EQ(c.real("material.rho"), 2643.0);
}

TEST(CaseLoad, DottedKeysAndInlineTables)
{
  const Case c = load_text("material.E = 20e9\nmesh = { order = 1 }\n");
  EXPECT_DOUBLE_EQ(c.real("material.E"), 20e9);
  EXPECT_EQ(c.integer("mesh.order"), 1);
}

TEST(CaseLoad, Overrides)
{
  const Case c = Case::load(make_schema(), data_dir / "dam.toml",
                            {"material.E=32e9", "material.nu = 0.25",
                             "material.rho=2400", // integer for a real
                             "mesh.order=2", "mesh.refine=true",
                             "output.stress=static", // bare string
                             "title=\"Quoted title\"", "mesh.file='lit.msh'",
                             "damping.modes=[2,4, 6]",
                             "damping.ratios=0.02,0.03", // no brackets
                             "time.dt=0.005",
                             "time.dt=0.002", // the last one wins
                             "output.vtk.every=1"});
  EXPECT_DOUBLE_EQ(c.real("material.E"), 32e9);
  EXPECT_DOUBLE_EQ(c.real("material.nu"), 0.25);
  EXPECT_DOUBLE_EQ(c.real("material.rho"), 2400.0);
  EXPECT_EQ(c.integer("mesh.order"), 2);
  EXPECT_TRUE(c.boolean("mesh.refine"));
  EXPECT_EQ(c.string("output.stress"), "static");
  EXPECT_EQ(c.string("title"), "Quoted title");
  EXPECT_EQ(c.string("mesh.file"), "lit.msh");
  EXPECT_EQ(c.integers("damping.modes"), (std::vector<std::int64_t>{2, 4, 6}));
  EXPECT_EQ(c.reals("damping.ratios"), (std::vector<double>{0.02, 0.03}));
  EXPECT_DOUBLE_EQ(c.real("time.dt"), 0.002);
  EXPECT_EQ(c.integer("output.vtk.every"), 1);
  EXPECT_TRUE(c.is_set("material.rho"));
  EXPECT_TRUE(c.is_set("damping.ratios"));
}

TEST(CaseLoad, BareStringOverrides)
{
  // Words that would parse as other TOML types stay strings for string keys.
  EXPECT_EQ(load_text("", {"title=true"}).string("title"), "true");
  EXPECT_EQ(load_text("", {"title=1.5"}).string("title"), "1.5");
  EXPECT_EQ(load_text("", {"title=a b=c"}).string("title"), "a b=c");
  EXPECT_EQ(load_text("", {"title="}).string("title"), "");
  EXPECT_EQ(load_text("", {"damping.modes=[]"}).integers("damping.modes"),
            std::vector<std::int64_t>{});
  EXPECT_EQ(load_text("", {"damping.modes=5"}).integers("damping.modes"),
            std::vector<std::int64_t>{5});
}

TEST(CaseLoad, OverrideRepairsFileValue)
{
  // Bounds apply to the final value.
  const Case c = load_text("[material]\nnu = 0.7\n", {"material.nu=0.3"});
  EXPECT_DOUBLE_EQ(c.real("material.nu"), 0.3);
}

TEST(CaseLoad, InclusiveBoundsAccepted)
{
  const Case c = load_text("[mesh]\norder = 1\n[damping]\nratios = [0, 1]\n");
  EXPECT_EQ(c.integer("mesh.order"), 1);
  EXPECT_EQ(load_text("", {"mesh.order=2"}).integer("mesh.order"), 2);
  EXPECT_DOUBLE_EQ(load_text("", {"material.nu=-0.999"}).real("material.nu"),
                   -0.999);
}

TEST(CaseLoad, PathIsRelativeToCaseFile)
{
  const Case c = Case::load(make_schema(), data_dir / "dam.toml");
  EXPECT_EQ(c.path("mesh.file"), data_dir / "meshes" / "koyna.msh");
  const Case d = Case::load(make_schema(), data_dir / "dam.toml",
                            {"mesh.file=/abs/dam.msh"});
  EXPECT_EQ(d.path("mesh.file"), fs::path("/abs/dam.msh"));
  const Case e = Case::load(make_schema(), data_dir / "dam.toml",
                            {"mesh.file=../up/dam.msh"});
  EXPECT_EQ(e.path("mesh.file"), data_dir.parent_path() / "up" / "dam.msh");
  const Case f =
      Case::load(make_schema(), data_dir / "dam.toml", {"mesh.file=\"\""});
  EXPECT_TRUE(f.path("mesh.file").empty());
}

TEST(CaseLoad, ToTomlRoundTrips)
{
  TempDir dir;
  const Case c = Case::load(make_schema(), data_dir / "dam.toml",
                            {"title=\"He said \\\"hi\\\"\\tC:\\\\x\\nnext é\"",
                             "material.E=3.3e10", "material.nu=0.1",
                             "damping.ratios=[0.1, 1, 2e-3]",
                             "damping.modes=[]", "mesh.refine=true"});
  EXPECT_EQ(c.string("title"), "He said \"hi\"\tC:\\x\nnext é");
  // A key read as a path is written absolute: the saved case, elsewhere,
  // names the same file.
  const fs::path mesh = c.path("mesh.file");
  const std::string text = c.to_toml();
  const Case r = Case::load(make_schema(), dir.write("saved.toml", text));
  EXPECT_EQ(r.path("mesh.file"), fs::absolute(mesh).lexically_normal());
  const Schema schema = make_schema();
  for (const Key& key : schema.keys())
  {
    SCOPED_TRACE(key.path);
    // The defaults stay defaults (commented out), the given keys given.
    EXPECT_EQ(r.is_set(key.path), c.is_set(key.path));
    switch (key.type)
    {
    case Type::boolean:
      EXPECT_EQ(r.boolean(key.path), c.boolean(key.path));
      break;
    case Type::integer:
      EXPECT_EQ(r.integer(key.path), c.integer(key.path));
      break;
    case Type::real:
      EXPECT_EQ(r.real(key.path), c.real(key.path)); // exactly
      break;
    case Type::string:
      if (key.path == "mesh.file") // the same file, named absolute
        EXPECT_EQ(r.path(key.path), c.path(key.path));
      else
        EXPECT_EQ(r.string(key.path), c.string(key.path));
      break;
    case Type::real_array:
      EXPECT_EQ(r.reals(key.path), c.reals(key.path));
      break;
    case Type::integer_array:
      EXPECT_EQ(r.integers(key.path), c.integers(key.path));
      break;
    case Type::string_array:
      EXPECT_EQ(r.strings(key.path), c.strings(key.path));
      break;
    }
  }
  // Written again: identical, but for the header naming the file.
  const std::string again = r.to_toml();
  EXPECT_EQ(again.substr(again.find("\n[")), text.substr(text.find("\n[")));
  EXPECT_NE(text.find("\n# rho = 2643.0  # [kg/m^3] Mass density (default)\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("[output.vtk]"), std::string::npos) << text;
  EXPECT_NE(text.find("\n# --set material.E=3.3e10\n"), std::string::npos)
      << text;
}

TEST(CaseLoad, StringArrays)
{
  Schema schema;
  schema.string_array("regions.groups", "[\"dam\"]", "-", "mesh groups");
  const auto dir = std::filesystem::temp_directory_path();
  const auto file = dir / "damseis_string_array.toml";
  std::ofstream(file) << "[regions]\ngroups = [\"dam\", \"rock 1\"]\n";
  Case c = Case::load(schema, file);
  EXPECT_EQ(c.strings("regions.groups"),
            (std::vector<std::string>{"dam", "rock 1"}));
  // --set: TOML, or bare words with or without brackets.
  for (const std::string set : {"regions.groups=[\"a\", \"b\"]",
                                "regions.groups=a, b", "regions.groups=[a,b]"})
  {
    Case o = Case::load(schema, file, {set});
    EXPECT_EQ(o.strings("regions.groups"), (std::vector<std::string>{"a", "b"}))
        << set;
  }
  // A number in the array is refused with one line naming the key.
  std::ofstream(file) << "[regions]\ngroups = [\"dam\", 3]\n";
  try
  {
    Case::load(schema, file);
    FAIL() << "accepted a number in a string array";
  }
  catch (const InputError& e)
  {
    EXPECT_NE(std::string(e.what()).find("regions.groups"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("array of strings"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(schema.string_array("regions.x", "[1]", "-", ""),
               std::logic_error);
  std::filesystem::remove(file);
}

TEST(CaseLoad, ProgrammingErrorsAreLogicErrors)
{
  const Case c = load_text("");
  EXPECT_THROW(c.real("material.G"), std::logic_error);
  EXPECT_THROW(c.integer("material.E"), std::logic_error);
  EXPECT_THROW(c.real("mesh.order"), std::logic_error);
  EXPECT_THROW(c.reals("damping.modes"), std::logic_error);
  EXPECT_THROW(c.path("mesh.order"), std::logic_error);
  EXPECT_THROW((void)c.is_set("nope"), std::logic_error);
}

TEST(CaseLoad, FailNamesFileAndKey)
{
  const Case c = Case::load(make_schema(), data_dir / "dam.toml");
  const std::string message = expect_input_error(
      [&] { c.fail("mesh.order", "order 1 needs\na finer mesh", "order 2"); },
      {"dam.toml: mesh.order: order 1 needs", "; expected order 2"});
}

// ---------------------------------------------------------------------------
// Errors in the input
// ---------------------------------------------------------------------------

TEST(CaseErrors, MissingFile)
{
  expect_input_error(
      [] { Case::load(make_schema(), data_dir / "no_such_case.toml"); },
      {"no_such_case.toml", "not found"});
  expect_input_error([] { Case::load(make_schema(), data_dir); },
                     {"directory"});
}

TEST(CaseErrors, MalformedToml)
{
  expect_load_error("[material]\nE = = 3\n",
                    {"bad_case.toml:2:", "malformed TOML"});
  expect_load_error("title = \"unterminated\n", {"bad_case.toml:1:"});
  expect_load_error("[material]\nE = 1\nE = 2\n", {"bad_case.toml:3:"});
}

TEST(CaseErrors, UnknownKeySuggestsClosest)
{
  expect_load_error("[material]\nEE = 1\n",
                    {"unknown key material.EE", "did you mean material.E?"});
  expect_load_error("[materal]\nnu = 0.3\n",
                    {"unknown key materal.nu", "did you mean material.nu?"});
  expect_load_error("[material]\ne = 3\n", {"did you mean material.E?"});
  expect_load_error("E = 3\n", {"unknown key E", "did you mean material.E?"});
  expect_load_error("[mesh]\norder = 1\nordr = 2\n",
                    {"unknown key mesh.ordr", "did you mean mesh.order?"});
  const std::string message =
      expect_load_error("[foo]\nbar = 1\n", {"unknown key foo.bar"});
  EXPECT_EQ(message.find("did you mean"), std::string::npos) << message;
  expect_load_error("[nothing]\n", {"unknown key nothing"});
}

TEST(CaseErrors, WrongType)
{
  expect_load_error(
      "[material]\nE = \"abc\"\n",
      {"material.E = \"abc\" is a string; expected a number (Pa)"});
  expect_load_error("[mesh]\norder = 2.0\n",
                    {"mesh.order = 2.0 is a float; expected an integer"});
  expect_load_error("[mesh]\nrefine = 1\n",
                    {"mesh.refine = 1 is an integer", "true or false"});
  expect_load_error(
      "[damping]\nmodes = [1, 2.5]\n",
      {"damping.modes = [1, 2.5]", "a float", "expected an array of integers"});
  expect_load_error("[damping]\nmodes = 1\n",
                    {"damping.modes = 1 is an integer", "array"});
  expect_load_error("[material.E]\nx = 1\n",
                    {"material.E is a table", "a number"});
  expect_load_error("material = 3\n",
                    {"material = 3 is an integer", "table [material]"});
  expect_load_error("[time]\ndt = 2021-01-01\n", {"time.dt", "a date"});
  expect_load_error("[material]\nE = nan\n", {"material.E", "not a finite"});
  expect_load_error("[damping]\nratios = [0.1, inf]\n",
                    {"damping.ratios", "not a finite"});
}

TEST(CaseErrors, OutOfRange)
{
  // The example of the requirements, exactly.
  const std::string message = expect_load_error("[material]\nnu = 0.7\n", {});
  EXPECT_TRUE(message.ends_with(
      "bad_case.toml: material.nu = 0.7 is out of range; expected -1 < nu "
      "< 0.5"))
      << message;
  // Exclusive bounds reject the bound itself.
  expect_load_error("[material]\nnu = 0.5\n",
                    {"material.nu = 0.5 is out of range"});
  expect_load_error("[material]\nnu = -1\n",
                    {"material.nu = -1 is out of range"});
  expect_load_error("[material]\nE = 0\n",
                    {"material.E = 0 is out of range; expected E > 0"});
  expect_load_error("[material]\nE = -30e9\n", {"expected E > 0"});
  expect_load_error("[time]\ndt = 0.0\n", {"time.dt", "expected dt > 0"});
  expect_load_error("[mesh]\norder = 3\n", {"expected 1 <= order <= 2"});
  expect_load_error("[mesh]\norder = 0\n", {"expected 1 <= order <= 2"});
  expect_load_error("[damping]\nmodes = [1, 0]\n",
                    {"damping.modes = [1, 0]", "expected modes[i] >= 1"});
  expect_load_error("[damping]\nratios = [0.5, 1.01]\n",
                    {"expected 0 <= ratios[i] <= 1"});
  // Out of range through --set.
  expect_load_error("", {"--set material.nu=0.9 is out of range"},
                    {"material.nu=0.9"});
}

TEST(CaseErrors, BadChoice)
{
  expect_load_error("[output]\nstress = \"seismc\"\n",
                    {"output.stress = \"seismc\" is not an allowed value",
                     "one of \"static\", \"seismic\", \"total\"",
                     "did you mean \"seismic\"?"});
  expect_load_error("", {"--set output.stress=everything", "one of"},
                    {"output.stress=everything"});
}

TEST(CaseErrors, MalformedSet)
{
  expect_load_error("", {"--set material.E", "no '='", "key=value"},
                    {"material.E"});
  expect_load_error("", {"--set =3", "no key"}, {"=3"});
}

TEST(CaseErrors, UnknownSetKey)
{
  expect_load_error("",
                    {"--set material.EE=3", "unknown key material.EE",
                     "did you mean material.E?"},
                    {"material.EE=3"});
  expect_load_error("", {"unknown key mesh.oder", "did you mean mesh.order?"},
                    {"mesh.oder=1"});
}

TEST(CaseErrors, BadSetValue)
{
  expect_load_error("",
                    {"--set material.E=abc is not a valid TOML value",
                     "expected a number (Pa)"},
                    {"material.E=abc"});
  expect_load_error("", {"--set mesh.order=1.5 is a float"},
                    {"mesh.order=1.5"});
  expect_load_error("", {"--set mesh.refine=yes", "true or false"},
                    {"mesh.refine=yes"});
  expect_load_error("", {"--set damping.modes=[1,x]"}, {"damping.modes=[1,x]"});
  // A newline cannot smuggle in a second key; the message stays one line.
  expect_load_error("", {"material.E", "not a valid TOML value"},
                    {"material.E=1\nmaterial.nu=0.7"});
}

// ---------------------------------------------------------------------------
// Command line
// ---------------------------------------------------------------------------

namespace
{

std::optional<CommandLine> parse(std::vector<std::string> args)
{
  args.insert(args.begin(), "koyna");
  std::vector<char*> argv;
  for (auto& arg : args)
    argv.push_back(arg.data());
  argv.push_back(nullptr);
  return parse_command_line(static_cast<int>(args.size()), argv.data(), "koyna",
                            "/demos/koyna/koyna.toml", make_schema());
}

} // namespace

TEST(CommandLine, Defaults)
{
  const auto cl = parse({});
  ASSERT_TRUE(cl);
  EXPECT_EQ(cl->case_file, fs::path("/demos/koyna/koyna.toml"));
  EXPECT_EQ(cl->out_dir, fs::path("out/koyna"));
  EXPECT_TRUE(cl->overrides.empty());
}

TEST(CommandLine, Options)
{
  const auto cl =
      parse({"--case", "my.toml", "--out", "/tmp/results", "--set",
             "material.E=31.027e9", "--set", "mesh.order=1", "--set=a=b=c",
             "--set", "damping.modes=[1,3]", "output.stress=seismic"});
  ASSERT_TRUE(cl);
  EXPECT_EQ(cl->case_file, fs::path("my.toml"));
  EXPECT_EQ(cl->out_dir, fs::path("/tmp/results"));
  EXPECT_EQ(cl->overrides,
            (std::vector<std::string>{"material.E=31.027e9", "mesh.order=1",
                                      "a=b=c", "damping.modes=[1,3]",
                                      "output.stress=seismic"}));
}

TEST(CommandLine, HelpReturnsNullopt)
{
  for (const std::string flag : {"--help", "-h"})
  {
    testing::internal::CaptureStdout();
    const auto cl = parse({"--set", "mesh.order=1", flag});
    const std::string out = testing::internal::GetCapturedStdout();
    EXPECT_FALSE(cl);
    for (const std::string part :
         {"koyna", "--case", "--out", "--set", "material.E", "Pa",
          "Young's modulus", "[E > 0]", "/demos/koyna/koyna.toml"})
      EXPECT_NE(out.find(part), std::string::npos) << part << "\n" << out;
  }
}

TEST(CommandLine, BadArgumentsThrowInputError)
{
  expect_input_error([] { parse({"--bogus"}); }, {"koyna", "--bogus"});
  expect_input_error([] { parse({"--case"}); }, {"koyna", "--case"});
  expect_input_error([] { parse({"--set"}); }, {"koyna", "--set"});
  expect_input_error(
      [] {
        parse({"--out", "a", "stray.toml"});
      },
      {"koyna", "stray.toml"});
}

TEST(CommandLine, WithCaseLoad)
{
  // The two pieces together, as in a demo's main.
  const auto cl = parse(
      {"--case", (data_dir / "dam.toml").string(), "--set", "material.nu=0.3"});
  ASSERT_TRUE(cl);
  const Case c = Case::load(make_schema(), cl->case_file, cl->overrides);
  EXPECT_DOUBLE_EQ(c.real("material.nu"), 0.3);
  EXPECT_DOUBLE_EQ(c.real("material.E"), 31.027e9);
}

TEST(InputError, IsOnePrintableLineWithLongWordsShortened)
{
  const std::string key(5000, 'k');
  const damseis::input::InputError e("case.toml: unknown key " + key +
                                     " \nsecond\tline; expected a key");
  const std::string what = e.what();
  EXPECT_EQ(what.find('\n'), std::string::npos);
  EXPECT_EQ(what.find('\t'), std::string::npos);
  EXPECT_LT(what.size(), 300u) << what;
  EXPECT_NE(what.find("...(5000 characters)..."), std::string::npos) << what;
  EXPECT_NE(what.find("; expected a key"), std::string::npos) << what;
  // A long word of two-byte UTF-8 characters is cut between characters.
  std::string accents;
  for (int i = 0; i < 300; ++i)
    accents += "\xc3\xa9";
  const std::string cut = damseis::input::InputError(accents).what();
  EXPECT_EQ(cut.find("\xc3..."), std::string::npos);
  EXPECT_EQ(cut.rfind("\xa9", 0), std::string::npos);
}
