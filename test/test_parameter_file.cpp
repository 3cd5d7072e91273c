// Parameter files (eaci/planner/parameter_file.hpp): the CLI's --params reading, as one core function.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "eaci/planner/parameter_file.hpp"

namespace eaci {
namespace {

// The ParameterFileError message of applying `text`, or "" when it applies cleanly.
std::string errorOf(const std::string& text, Parameters* out = nullptr) {
  Parameters p;
  try {
    applyParameterYaml(text, p, "--params 'p.yaml'");
  } catch (const ParameterFileError& e) {
    return e.what();
  }
  if (out != nullptr) *out = p;
  return "";
}

bool startsWith(const std::string& text, const std::string& prefix) { return text.rfind(prefix, 0) == 0; }
bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(ParameterFile, AppliesEachKeyInOrderOnTopOfTheGivenValues) {
  Parameters p;
  p.ants = 3;
  p.max_iterations = 9;
  applyParameterYaml("# tuned\nants: 7\nallow_corner_cutting: True\nseed: 11\nants: 8\n", p, "x");
  EXPECT_EQ(p.ants, 8);             // the later line wins
  EXPECT_EQ(p.max_iterations, 9);   // untouched
  EXPECT_TRUE(p.allow_corner_cutting);  // YAML's "True" spelling
  EXPECT_EQ(p.seed, 11u);
  Parameters q;
  applyParameterYaml("allow_corner_cutting: no\n", q);
  EXPECT_FALSE(q.allow_corner_cutting);
  // Flow style is a mapping too.
  EXPECT_EQ(errorOf("{ants: 12, max_iterations: 30}", &q), "");
  EXPECT_EQ(q.ants, 12);
  EXPECT_EQ(q.max_iterations, 30);
}

TEST(ParameterFile, EachBadShapeIsOneLineNamingTheSourceAndTheKey) {
  struct Case {
    const char* text;
    const char* part;
  } cases[] = {
      {"ants: 10\nnot_a_parameter: 3\n", "not_a_parameter"},
      {"ants: many\n", "ants"},
      {"ants:\n", "'ants' has no value"},
      {"ants: [1, 2]\n", "'ants' must be a single value"},
      {"eaci_planner:\n  ants: 10\n", "'eaci_planner' must be a single value"},
      {"[a, b]: 1\n", "parameter names must be plain words"},
      {"- ants\n- 10\n", "got a list"},
      {"just some words\n", "got a single value"},
      {"", "got an empty document"},
      {"ants: [1, 2\nbeta: {\n", "is not valid YAML"},
  };
  for (const Case& c : cases) {
    const std::string message = errorOf(c.text);
    EXPECT_TRUE(startsWith(message, "--params 'p.yaml'")) << c.text << " -> " << message;
    EXPECT_TRUE(has(message, c.part)) << c.text << " -> " << message;
    EXPECT_FALSE(has(message, "\n")) << c.text;
  }
}

TEST(ParameterFile, TooDeeplyNestedYamlNamesTheFileNotABadFile) {
  // yaml-cpp 0.7 stops at its nesting limit with "error at line 1, column 1: bad file".
  for (const std::string& text : {std::string(100000, '['), "ants: " + std::string(5000, '{')}) {
    const std::string message = errorOf(text);
    EXPECT_TRUE(startsWith(message, "--params 'p.yaml' is not valid YAML")) << message.substr(0, 200);
    EXPECT_TRUE(has(message, "nested")) << message.substr(0, 200);
    EXPECT_FALSE(has(message, "bad file")) << message.substr(0, 200);
  }
}

TEST(ParameterFile, ReadsFilesAndNamesTheOnesItCannotOpen) {
  const std::string path = ::testing::TempDir() + "eaci_parameter_file_test.yaml";
  std::ofstream(path) << "ants: 21\n";
  Parameters p;
  applyParameterFile(path, p, "--params '" + path + "'");
  EXPECT_EQ(p.ants, 21);
  std::remove(path.c_str());
  try {
    applyParameterFile(path, p, "--params '" + path + "'");
    ADD_FAILURE() << "a missing file was read";
  } catch (const ParameterFileError& e) {
    EXPECT_EQ(std::string(e.what()), "--params '" + path + "': cannot open the file");
  }
}

// parameterYaml -> applyParameterYaml gives back every value exactly (numbers that have no
// short decimal form included), so a planner's settings can be replayed with --params.
TEST(ParameterFile, ParameterYamlReadsBackToTheSameValues) {
  Parameters p;
  p.ants = 17;
  p.alpha = 0.1 + 0.2;  // 0.30000000000000004
  p.neutral_cost = 1.0 / 3.0;
  p.cost_factor = 2.5e-7;
  p.lethal_cost = 200;
  p.allow_unknown = true;
  p.allow_corner_cutting = true;
  p.island_strategy = IslandStrategy::kPaper;
  p.seed = 18446744073709551615u;
  Parameters q;
  applyParameterYaml(parameterYaml(p), q, "saved");
  EXPECT_EQ(parameterValues(q), parameterValues(p));
  EXPECT_TRUE(has(parameterYaml(p), "lethal_cost: 200\n")) << parameterYaml(p);
}

}  // namespace
}  // namespace eaci
