#include "service/config.h"

#include <gtest/gtest.h>

#include <chrono>
#include <map>
#include <string>
#include <vector>

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

TEST(Config, CalculationPoolFlagsSetThreadsAndQueue) {
  const ConfigOutcome defaults = parse({});
  ASSERT_TRUE(defaults.config);
  EXPECT_EQ(defaults.config->http.calculation_threads, 0U);  // as many as the event loops
  const ConfigOutcome outcome = parse({"--calculation-threads", "3", "--calculation-queue=40"});
  ASSERT_TRUE(outcome.config) << outcome.message;
  EXPECT_EQ(outcome.config->http.calculation_threads, 3U);
  EXPECT_EQ(outcome.config->http.calculation_queue_limit, 40U);
  const ConfigOutcome env =
      parse({}, {{"CUTCALC_CALCULATION_THREADS", "256"}, {"CUTCALC_CALCULATION_QUEUE", "100000"}});
  ASSERT_TRUE(env.config) << env.message;
  EXPECT_EQ(env.config->http.calculation_threads, 256U);
  EXPECT_EQ(env.config->http.calculation_queue_limit, 100000U);
}

TEST(Config, CalculationPoolFlagsOutOfRangeExitWithStatus2) {
  for (const auto& args : std::vector<std::vector<std::string>>{{"--calculation-threads", "0"},
                                                                {"--calculation-threads", "257"},
                                                                {"--calculation-threads", "two"},
                                                                {"--calculation-queue", "0"},
                                                                {"--calculation-queue", "100001"},
                                                                {"--calculation-queue", "-1"},
                                                                {"--calculation-queue"}}) {
    const ConfigOutcome outcome = parse(args);
    EXPECT_FALSE(outcome.config) << args[0] << " " << (args.size() > 1 ? args[1] : "");
    EXPECT_EQ(outcome.exit_code, 2);
    EXPECT_NE(outcome.message.find(args[0]), std::string::npos) << outcome.message;
  }
  const ConfigOutcome env = parse({}, {{"CUTCALC_CALCULATION_THREADS", "1000"}});
  EXPECT_FALSE(env.config);
  EXPECT_NE(env.message.find("CUTCALC_CALCULATION_THREADS"), std::string::npos);
}

TEST(Config, ReusePortIsOffUnlessAskedFor) {
  const ConfigOutcome defaults = parse({});
  ASSERT_TRUE(defaults.config);
  EXPECT_FALSE(defaults.config->http.reuse_port);
  // A bare flag means on, and does not take the next argument as its value.
  const ConfigOutcome bare = parse({"--reuse-port", "--port", "9001"});
  ASSERT_TRUE(bare.config) << bare.message;
  EXPECT_TRUE(bare.config->http.reuse_port);
  EXPECT_EQ(bare.config->port, 9001);
  const ConfigOutcome last = parse({"--port", "9001", "--reuse-port"});
  ASSERT_TRUE(last.config) << last.message;
  EXPECT_TRUE(last.config->http.reuse_port);
  for (const std::string value : {"on", "true", "1"}) {
    const ConfigOutcome on = parse({"--reuse-port=" + value});
    ASSERT_TRUE(on.config) << on.message;
    EXPECT_TRUE(on.config->http.reuse_port) << value;
  }
  for (const std::string value : {"off", "false", "0"}) {
    const ConfigOutcome off = parse({"--reuse-port=" + value}, {{"CUTCALC_REUSE_PORT", "on"}});
    ASSERT_TRUE(off.config) << off.message;
    EXPECT_FALSE(off.config->http.reuse_port) << value;
  }
  const ConfigOutcome env = parse({}, {{"CUTCALC_REUSE_PORT", "on"}});
  ASSERT_TRUE(env.config) << env.message;
  EXPECT_TRUE(env.config->http.reuse_port);
  const ConfigOutcome env_off = parse({}, {{"CUTCALC_REUSE_PORT", "off"}});
  ASSERT_TRUE(env_off.config) << env_off.message;
  EXPECT_FALSE(env_off.config->http.reuse_port);
}

TEST(Config, ReusePortRejectsOtherValues) {
  const ConfigOutcome flag = parse({"--reuse-port=yes-please"});
  EXPECT_FALSE(flag.config);
  EXPECT_EQ(flag.exit_code, 2);
  EXPECT_NE(flag.message.find("--reuse-port"), std::string::npos) << flag.message;
  const ConfigOutcome env = parse({}, {{"CUTCALC_REUSE_PORT", "maybe"}});
  EXPECT_FALSE(env.config);
  EXPECT_EQ(env.exit_code, 2);
  EXPECT_NE(env.message.find("CUTCALC_REUSE_PORT"), std::string::npos) << env.message;
}

TEST(Config, CalculationTimeoutAndMemoryLimitFlagsSetThem) {
  const ConfigOutcome defaults = parse({});
  ASSERT_TRUE(defaults.config);
  EXPECT_EQ(defaults.config->http.limits.calculation_timeout, std::chrono::milliseconds(30000));
  EXPECT_EQ(defaults.config->http.memory_limit_bytes, 0U);  // the cgroup's

  const ConfigOutcome flags = parse({"--calculation-timeout-ms", "1", "--memory-limit-mb=64"});
  ASSERT_TRUE(flags.config) << flags.message;
  EXPECT_EQ(flags.config->http.limits.calculation_timeout, std::chrono::milliseconds(1));
  EXPECT_EQ(flags.config->http.memory_limit_bytes, 64U * 1024 * 1024);

  const ConfigOutcome env = parse(
      {}, {{"CUTCALC_CALCULATION_TIMEOUT_MS", "3600000"}, {"CUTCALC_MEMORY_LIMIT_MB", "1048576"}});
  ASSERT_TRUE(env.config) << env.message;
  EXPECT_EQ(env.config->http.limits.calculation_timeout, std::chrono::milliseconds(3600000));
  EXPECT_EQ(env.config->http.memory_limit_bytes, 1048576ULL * 1024 * 1024);

  for (const std::vector<std::string>& bad :
       std::vector<std::vector<std::string>>{{"--calculation-timeout-ms", "0"},
                                             {"--calculation-timeout-ms", "3600001"},
                                             {"--memory-limit-mb", "63"},
                                             {"--memory-limit-mb", "x"}}) {
    const ConfigOutcome outcome = parse(bad);
    EXPECT_FALSE(outcome.config) << bad[0] << ' ' << bad[1];
    EXPECT_EQ(outcome.exit_code, 2);
    EXPECT_NE(outcome.message.find(bad[0]), std::string::npos) << outcome.message;
  }
}

TEST(Config, RestartAndConnectionFlagsSetTheirLimits) {
  const ConfigOutcome defaults = parse({});
  ASSERT_TRUE(defaults.config);
  // Above the usual proxies' 60 s idle timeout; a lame duck a 1 s health check sees twice.
  EXPECT_EQ(defaults.config->http.limits.keep_alive_timeout, std::chrono::seconds(75));
  EXPECT_EQ(defaults.config->http.limits.lame_duck, std::chrono::milliseconds(3000));
  EXPECT_EQ(defaults.config->http.max_connections, 0U);  // from the memory and descriptor limits

  const ConfigOutcome flags =
      parse({"--keep-alive-timeout-s", "90", "--lame-duck-ms=0", "--max-connections", "2000"});
  ASSERT_TRUE(flags.config) << flags.message;
  EXPECT_EQ(flags.config->http.limits.keep_alive_timeout, std::chrono::seconds(90));
  EXPECT_EQ(flags.config->http.limits.lame_duck, std::chrono::milliseconds(0));
  EXPECT_EQ(flags.config->http.max_connections, 2000U);

  const ConfigOutcome env = parse({}, {{"CUTCALC_KEEP_ALIVE_TIMEOUT_S", "3600"},
                                       {"CUTCALC_LAME_DUCK_MS", "600000"},
                                       {"CUTCALC_MAX_CONNECTIONS", "1000000"}});
  ASSERT_TRUE(env.config) << env.message;
  EXPECT_EQ(env.config->http.limits.keep_alive_timeout, std::chrono::seconds(3600));
  EXPECT_EQ(env.config->http.limits.lame_duck, std::chrono::milliseconds(600000));
  EXPECT_EQ(env.config->http.max_connections, 1000000U);

  const ConfigOutcome lowest = parse({"--keep-alive-timeout-s", "1", "--max-connections", "1"},
                                     {{"CUTCALC_LAME_DUCK_MS", "5000"}});
  ASSERT_TRUE(lowest.config) << lowest.message;
  EXPECT_EQ(lowest.config->http.limits.keep_alive_timeout, std::chrono::seconds(1));
  EXPECT_EQ(lowest.config->http.limits.lame_duck, std::chrono::milliseconds(5000));
  EXPECT_EQ(lowest.config->http.max_connections, 1U);

  const ConfigOutcome overridden =
      parse({"--lame-duck-ms", "250"}, {{"CUTCALC_LAME_DUCK_MS", "5000"}});
  ASSERT_TRUE(overridden.config) << overridden.message;
  EXPECT_EQ(overridden.config->http.limits.lame_duck, std::chrono::milliseconds(250));
}

TEST(Config, RestartAndConnectionFlagsOutOfRangeExitWithStatus2) {
  for (const auto& args : std::vector<std::vector<std::string>>{{"--keep-alive-timeout-s", "0"},
                                                                {"--keep-alive-timeout-s", "3601"},
                                                                {"--keep-alive-timeout-s", "1.5"},
                                                                {"--lame-duck-ms", "-1"},
                                                                {"--lame-duck-ms", "600001"},
                                                                {"--lame-duck-ms", "soon"},
                                                                {"--max-connections", "0"},
                                                                {"--max-connections", "1000001"},
                                                                {"--max-connections"}}) {
    const ConfigOutcome outcome = parse(args);
    EXPECT_FALSE(outcome.config) << args[0] << " " << (args.size() > 1 ? args[1] : "");
    EXPECT_EQ(outcome.exit_code, 2);
    EXPECT_NE(outcome.message.find(args[0]), std::string::npos) << outcome.message;
  }
  for (const char* name :
       {"CUTCALC_KEEP_ALIVE_TIMEOUT_S", "CUTCALC_LAME_DUCK_MS", "CUTCALC_MAX_CONNECTIONS"}) {
    const ConfigOutcome env = parse({}, {{name, "-5"}});
    EXPECT_FALSE(env.config) << name;
    EXPECT_EQ(env.exit_code, 2) << name;
    EXPECT_NE(env.message.find(name), std::string::npos) << env.message;
  }
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
