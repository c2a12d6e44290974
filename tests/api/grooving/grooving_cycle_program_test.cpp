// Every grooving reference request (next/grooving-cycle.json) in every dialect and unit: the text
// rules of programs.md section 3, the contract, the file name, and the facts that hold whatever
// the dialect: the title comment, one pattern block per revolution.

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "support/program_text_rules.h"
#include "support/project_contract.h"
#include "support/reference_cases.h"
#include "support/route_paths.h"

namespace cutcalc::testing {
namespace {

using nlohmann::json;

std::vector<json> grooving_ok_requests() {
  std::vector<json> requests;
  for (const ReferenceCase& c : load_cases("next/grooving-cycle.json")) {
    if (c.data.at("expect").at("status") == 200) requests.push_back(c.data.at("request"));
  }
  return requests;
}

int count_of(const std::string& text, const std::string& what) {
  int count = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) {
    ++count;
  }
  return count;
}

TEST(GroovingCycleProgram, ReferenceCasesAreLoadedOnce) {
  const auto cases = load_cases("next/grooving-cycle.json");
  ASSERT_FALSE(cases.empty());
  std::set<std::string> ids;
  for (const ReferenceCase& c : cases) {
    EXPECT_TRUE(ids.insert(c.data.at("id").get<std::string>()).second) << c.data.at("id");
  }
}

TEST(GroovingCycleProgram, EveryReferenceGrooveInEveryDialectAndUnitKeepsTheTextRules) {
  int checked = 0;
  for (const json& base : grooving_ok_requests()) {
    for (const char* dialect : {"linuxcnc", "fanuc", "sinumerik"}) {
      for (const char* units : {"mm", "inch"}) {
        json request = base;
        request["program"] = {{"dialect", dialect},
                              {"units", units},
                              {"tool_number", 4},
                              {"coolant", "flood"},
                              {"name", "RING_1"}};
        SCOPED_TRACE(request.dump());
        const JsonReply reply = post(kGroovingCyclePath, request.dump());
        expect_conforms(kGroovingCyclePath, reply);
        ASSERT_EQ(reply.status, 200) << reply.body;
        const std::string program = reply.json.at("program").get<std::string>();
        expect_text_rules(program, dialect);
        EXPECT_EQ(reply.json.at("dialect"), dialect);
        EXPECT_EQ(reply.json.at("units"), units);
        EXPECT_EQ(reply.json.at("file_name"), std::string(dialect) == "fanuc"       ? "O0001.nc"
                                              : std::string(dialect) == "sinumerik" ? "RING_1.MPF"
                                                                                    : "RING_1.ngc");
        EXPECT_NE(program.find("CUTCALC GROOVING CYCLE V RAZVOD"), std::string::npos);
        // Feed blocks: the air cut, N pattern blocks, the final shift (section 5.1).
        const char* feed = std::string(dialect) == "fanuc" ? "\nG01 " : "\nG1 ";
        EXPECT_EQ(count_of(program, feed), reply.json.at("revolutions").get<int>() + 2);
        ++checked;
      }
    }
  }
  EXPECT_GE(checked, 6 * 9);
}

}  // namespace
}  // namespace cutcalc::testing
