#include "service/config.h"

#include <gtest/gtest.h>

#include <map>
#include <string>

namespace cutcalc::service {
namespace {

ConfigOutcome parse(const std::vector<std::string>& args,
                    const std::map<std::string, std::string>& env = {}) {
  return parse_config(args, [&env](const char* name) -> const char* {
    const auto it = env.find(name);
    return it == env.end() ? nullptr : it->second.c_str();
  });
}

TEST(Config, DefaultsServeOnLoopback8080) {
  const ConfigOutcome outcome = parse({});
  ASSERT_TRUE(outcome.config);
  EXPECT_EQ(outcome.config->host, "127.0.0.1");
  EXPECT_EQ(outcome.config->port, 8080);
  EXPECT_EQ(outcome.config->log_level, "info");
  EXPECT_EQ(outcome.config->log_format, LogFormat::text);
}

TEST(Config, FlagsSetEverySetting) {
  const ConfigOutcome outcome = parse({"--host", "0.0.0.0", "--port=9000", "--threads", "16",
                                       "--log-level", "warn", "--log-format", "json"});
  ASSERT_TRUE(outcome.config) << outcome.message;
  EXPECT_EQ(outcome.config->host, "0.0.0.0");
  EXPECT_EQ(outcome.config->port, 9000);
  EXPECT_EQ(outcome.config->http.event_loop_threads, 16U);
  EXPECT_EQ(outcome.config->log_level, "warn");
  EXPECT_EQ(outcome.config->log_format, LogFormat::json);
}

TEST(Config, EnvironmentSetsAndFlagsOverride) {
  const ConfigOutcome outcome =
      parse({"--port", "7000"}, {{"CUTCALC_PORT", "9100"}, {"CUTCALC_LOG_LEVEL", "error"}});
  ASSERT_TRUE(outcome.config);
  EXPECT_EQ(outcome.config->port, 7000);
  EXPECT_EQ(outcome.config->log_level, "error");
}

TEST(Config, InvalidValuesExitWithStatus2AndSayWhy) {
  for (const auto& args : std::vector<std::vector<std::string>>{{"--port", "70000"},
                                                                {"--port", "80x"},
                                                                {"--threads", "0"},
                                                                {"--log-level", "loud"},
                                                                {"--log-format", "xml"},
                                                                {"--bogus", "1"},
                                                                {"--port"}}) {
    const ConfigOutcome outcome = parse(args);
    EXPECT_FALSE(outcome.config) << args[0];
    EXPECT_EQ(outcome.exit_code, 2) << args[0];
    EXPECT_FALSE(outcome.message.empty());
  }
  const ConfigOutcome env = parse({}, {{"CUTCALC_PORT", "-1"}});
  EXPECT_FALSE(env.config);
  EXPECT_NE(env.message.find("CUTCALC_PORT"), std::string::npos);
}

TEST(Config, HelpAndVersionExitZero) {
  const ConfigOutcome help = parse({"--help"});
  EXPECT_FALSE(help.config);
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.message.find("--port"), std::string::npos);
  const ConfigOutcome version = parse({"--version"});
  EXPECT_FALSE(version.config);
  EXPECT_TRUE(version.print_version);
  const ConfigOutcome routes = parse({"--routes"});
  EXPECT_FALSE(routes.config);
  EXPECT_EQ(routes.exit_code, 0);
  EXPECT_TRUE(routes.print_routes);
  EXPECT_FALSE(parse({}).print_routes);
}

}  // namespace
}  // namespace cutcalc::service
