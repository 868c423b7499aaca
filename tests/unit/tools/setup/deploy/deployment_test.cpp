// Deployment files: the shipped ones place every process once; each kind of mistake is refused
// with an error naming its key.

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "sdlqr/config/config.hpp"
#include "sdlqr/deploy/deployment.hpp"
#include "test_paths.hpp"

namespace sdlqr::deploy {
namespace {

const std::string kStackTable = std::string(SDLQR_SOURCE_DIR) + "/config/stack.procs";

std::string writeTemp(const std::string& text) {
  const std::string path = sdlqr::test::tempPath(std::string("deployment_") +
                                                  ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".yaml");
  std::ofstream(path) << text;
  return path;
}

const char* const kValid = R"(name: two
lcm_url: "udpm://239.255.76.67:7667?ttl=1"
hosts:
  air: {address: 10.77.0.2, processes: [sim, lowlevel, estimator, gains, controller]}
  ground: {address: 10.77.0.3, processes: [mission, logger], receive_delay_ms: 20}
)";

// The error of loading `text`, which must fail.
std::string errorOf(const std::string& text) {
  try {
    loadDeployment(writeTemp(text), stackProcessNames(kStackTable));
  } catch (const ConfigError& e) {
    return e.what();
  }
  ADD_FAILURE() << "loaded:\n" << text;
  return "";
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST(Deployment, StackTableNamesEveryProcess) {
  const std::vector<std::string> names = stackProcessNames(kStackTable);
  EXPECT_EQ(names, (std::vector<std::string>{"logger", "estimator", "gains", "controller", "lowlevel", "mission", "sim"}));
}

TEST(Deployment, ShippedFilesPlaceEveryProcessOnce) {
  const std::vector<std::string> names = stackProcessNames(kStackTable);
  const Deployment three = loadDeployment(std::string(SDLQR_SOURCE_DIR) + "/config/deploy/three_hosts.yaml", names);
  ASSERT_EQ(three.hosts.size(), 3u);
  EXPECT_EQ(three.hostOf("lowlevel")->name, "vehicle");
  EXPECT_EQ(three.hostOf("sim")->name, "vehicle");
  EXPECT_EQ(three.hostOf("controller")->name, "companion");
  EXPECT_EQ(three.hostOf("logger")->name, "ground");
  EXPECT_EQ(three.monitor, "ground");
  EXPECT_TRUE(three.signing);
  const Deployment one = loadDeployment(std::string(SDLQR_SOURCE_DIR) + "/config/deploy/one_host.yaml", names);
  ASSERT_EQ(one.hosts.size(), 1u);
  EXPECT_FALSE(one.signing);
  for (const std::string& p : names) EXPECT_EQ(one.hostOf(p)->name, "host") << p;
}

TEST(Deployment, DescribesEveryHostOnOneLine) {
  const Deployment d = loadDeployment(writeTemp(kValid), stackProcessNames(kStackTable));
  EXPECT_EQ(describe(d),
            "name=two\nlcm_url=udpm://239.255.76.67:7667?ttl=1\nprefix_length=24\nmonitor=air\nsigning=on\n"
            "host=air 10.77.0.2 0 sim lowlevel estimator gains controller\n"
            "host=ground 10.77.0.3 20 mission logger\n");
}

TEST(Deployment, SigningIsOnAcrossHostsByDefaultAndSetByItsKey) {
  EXPECT_TRUE(loadDeployment(writeTemp(kValid), stackProcessNames(kStackTable)).signing);
  const std::string off = replaced(kValid, "hosts:\n", "signing: false\nhosts:\n");
  EXPECT_FALSE(loadDeployment(writeTemp(off), stackProcessNames(kStackTable)).signing);
  EXPECT_NE(errorOf(replaced(kValid, "hosts:\n", "signing: maybe\nhosts:\n")).find("signing: expected true or false"),
            std::string::npos);
}

TEST(Deployment, RefusesEachMistakeNamingItsKey) {
  EXPECT_NE(errorOf(replaced(kValid, "[mission, logger]", "[mission]")).find("hosts: process 'logger' is on no host"),
            std::string::npos);
  EXPECT_NE(errorOf(replaced(kValid, "[mission, logger]", "[mission, logger, sim]")).find("already on host air"),
            std::string::npos);
  EXPECT_NE(errorOf(replaced(kValid, "[mission, logger]", "[mission, logger, radio]")).find("'radio' is not a process"),
            std::string::npos);
  EXPECT_NE(errorOf(replaced(kValid, "10.77.0.3", "10.77.0.2")).find("hosts.ground.address: used by another host"),
            std::string::npos);
  EXPECT_NE(errorOf(replaced(kValid, "10.77.0.3", "10.78.0.3")).find("not in the subnet"), std::string::npos);
  EXPECT_NE(errorOf(replaced(kValid, "10.77.0.3", "10.77.0.255")).find("broadcast"), std::string::npos);
  EXPECT_NE(errorOf(replaced(kValid, "10.77.0.3", "10.77.0")).find("expected an IPv4 address"), std::string::npos);
  EXPECT_NE(errorOf(replaced(kValid, "?ttl=1", "?ttl=0")).find("lcm_url: needs ttl=1"), std::string::npos);
  EXPECT_NE(errorOf(replaced(kValid, "?ttl=1", "")).find("lcm_url: needs ttl=1"), std::string::npos);
  EXPECT_NE(errorOf(replaced(kValid, "udpm://", "tcpq://")).find("lcm_url: expected a udpm"), std::string::npos);
  EXPECT_NE(errorOf(replaced(kValid, "ground:", "Ground_Station:")).find("lower-case letters"), std::string::npos);
  EXPECT_NE(errorOf(replaced(kValid, "ground:", "groundstation1:")).find("1-12"), std::string::npos);
  EXPECT_NE(errorOf(replaced(kValid, "receive_delay_ms: 20", "receive_delay_ms: -1")).find("receive_delay_ms"),
            std::string::npos);
  EXPECT_NE(errorOf(replaced(kValid, "receive_delay_ms: 20", "delay: 20")).find("hosts.ground"), std::string::npos);
  EXPECT_NE(errorOf(replaced(kValid, "name: two", "name: two\nmonitor: tower")).find("monitor: no host 'tower'"),
            std::string::npos);
  EXPECT_NE(errorOf(replaced(kValid, "name: two", "nmae: two")).find("nmae"), std::string::npos);
}

TEST(Deployment, OneHostMayKeepTheDefaultTtl) {
  const Deployment d = loadDeployment(writeTemp("name: solo\nlcm_url: \"udpm://239.255.76.67:7667\"\nhosts:\n"
                                                "  box: {address: 10.77.0.2, processes: [logger, estimator, gains, "
                                                "controller, lowlevel, mission, sim]}\n"),
                                      stackProcessNames(kStackTable));
  EXPECT_EQ(d.hosts.size(), 1u);
}

}  // namespace
}  // namespace sdlqr::deploy

namespace sdlqr::deploy {
namespace {

TEST(Deployment, ThePx4DeploymentNamesItsOwnTableAndSignsItsMavlinkLink) {
  const std::string path = std::string(SDLQR_SOURCE_DIR) + "/config/deploy/px4_emulated.yaml";
  const std::string procs = deploymentProcs(path);
  EXPECT_EQ(procs, std::string(SDLQR_SOURCE_DIR) + "/config/deploy/../px4_emulated.procs");
  const Deployment d = loadDeployment(path, stackProcessNames(procs));
  EXPECT_EQ(d.hostOf("emulator")->name, "autopilot");
  EXPECT_EQ(d.hostOf("px4")->name, "companion");
  EXPECT_EQ(d.hostOf("controller")->name, "companion");
  EXPECT_TRUE(d.mavlink_signing);
  const std::string text = describe(d);
  EXPECT_NE(text.find("procs=" + procs + "\n"), std::string::npos);
  EXPECT_NE(text.find("mavlink_signing=on\n"), std::string::npos);
  EXPECT_EQ(deploymentProcs(std::string(SDLQR_SOURCE_DIR) + "/config/deploy/three_hosts.yaml"), "");
}

}  // namespace
}  // namespace sdlqr::deploy
