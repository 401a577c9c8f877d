#include "junit_report.h"

#include "physltl/common/files.h"
#include "physltl/common/printable.h"

#include <fmt/format.h>
#include <pugixml.hpp>

#include <sstream>
#include <stdexcept>

namespace physltl::app::scenario_test {
namespace {

std::string seconds(double s) { return fmt::format("{:.3f}", s); }

}  // namespace

void write_junit(const std::vector<ScenarioResult>& results, const std::filesystem::path& file) {
  pugi::xml_document doc;
  auto declaration = doc.append_child(pugi::node_declaration);
  declaration.append_attribute("version") = "1.0";
  declaration.append_attribute("encoding") = "UTF-8";
  pugi::xml_node suites = doc.append_child("testsuites");
  suites.append_attribute("name") = "physltl-studio test";
  int tests = 0, failures = 0, skipped = 0;
  double time_s = 0.0;
  for (const ScenarioResult& scenario : results) {
    pugi::xml_node suite = suites.append_child("testsuite");
    suite.append_attribute("name") = common::printable(scenario.label).c_str();
    suite.append_attribute("tests") = static_cast<int>(scenario.cases.size());
    suite.append_attribute("failures") = scenario.count(Outcome::kFailed);
    suite.append_attribute("errors") = 0;
    suite.append_attribute("skipped") = scenario.count(Outcome::kSkipped);
    suite.append_attribute("time") = seconds(scenario.time_s).c_str();
    for (const CaseResult& c : scenario.cases) {
      pugi::xml_node test = suite.append_child("testcase");
      test.append_attribute("name") = common::printable(c.name).c_str();
      test.append_attribute("classname") = common::printable(scenario.label).c_str();
      test.append_attribute("time") = seconds(c.time_s).c_str();
      if (c.outcome == Outcome::kFailed) {
        pugi::xml_node failure = test.append_child("failure");
        failure.append_attribute("message") = common::printable(c.message).c_str();
        failure.append_child(pugi::node_pcdata).set_value(common::printable(c.message).c_str());
      } else if (c.outcome == Outcome::kSkipped) {
        test.append_child("skipped").append_attribute("message") = common::printable(c.message).c_str();
      } else if (c.outcome == Outcome::kUpdated) {
        test.append_child("system-out").append_child(pugi::node_pcdata).set_value(common::printable(c.message).c_str());
      }
    }
    tests += static_cast<int>(scenario.cases.size());
    failures += scenario.count(Outcome::kFailed);
    skipped += scenario.count(Outcome::kSkipped);
    time_s += scenario.time_s;
  }
  suites.append_attribute("tests") = tests;
  suites.append_attribute("failures") = failures;
  suites.append_attribute("errors") = 0;
  suites.append_attribute("skipped") = skipped;
  suites.append_attribute("time") = seconds(time_s).c_str();

  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
  std::ostringstream xml;
  doc.save(xml, "  ", pugi::format_default, pugi::encoding_utf8);
  common::write_text_file(file, xml.str());
}

}  // namespace physltl::app::scenario_test
