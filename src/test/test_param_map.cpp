#include <gtest/gtest.h>

#include "asv_core/common/param_map.h"

using asv::ParamMap;

TEST(ParamMap, TypedGettersDefaultsAndErrors) {
  ParamMap p({{"aco/ants", "10"}, {"aco/rho", "0.1"}, {"flag", "true"}, {"name", "aco"}, {"bad", "1.5x"}});
  EXPECT_EQ(p.getInt("aco/ants", 3), 10);
  EXPECT_DOUBLE_EQ(p.getDouble("aco/rho", 0.5), 0.1);
  EXPECT_TRUE(p.getBool("flag", false));
  EXPECT_EQ(p.getString("name", ""), "aco");
  EXPECT_DOUBLE_EQ(p.getDouble("missing", 2.5), 2.5);
  EXPECT_THROW(p.getDouble("bad", 0.0), std::invalid_argument);
  EXPECT_THROW(p.getInt("aco/rho", 0), std::invalid_argument);
  ParamMap n;
  n.set("x", "nan");
  EXPECT_THROW(n.getDouble("x", 0.0), std::invalid_argument);
}

TEST(ParamMap, UnknownKeysAreReported) {
  ParamMap p({{"ants", "10"}, {"antz", "5"}});
  p.getInt("ants", 1);
  ASSERT_EQ(p.unknownKeys().size(), 1u);
  EXPECT_EQ(p.unknownKeys()[0], "antz");
  try {
    p.rejectUnknown("aco");
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'antz'"), std::string::npos);
  }
}

TEST(ParamMap, SubTreeAndRoundTripOfDoubles) {
  ParamMap p;
  p.set("aco/tau0", 1.0);
  p.set("aco/rho", 0.1);
  p.set("ga/pc", 0.7);
  const ParamMap aco = p.sub("aco");
  EXPECT_EQ(aco.values().size(), 2u);
  EXPECT_DOUBLE_EQ(aco.getDouble("rho", 0), 0.1);  // 17 significant digits survive the text form
}

// Values from a typed source (the ROS parameter server) keep their type: a getter of another type
// refuses them as roscpp's getParam does, naming the parameter with the map's label.
TEST(ParamMap, TypedValuesFollowRoscppRules) {
  ParamMap p;
  p.setLabel("/pe/");
  p.set("rate", "30", asv::ParamType::Int);
  p.set("pretty", "1", asv::ParamType::Int);
  p.set("name", "5", asv::ParamType::Int);
  p.set("gain", "0.5", asv::ParamType::Double);
  p.set("flag", "true", asv::ParamType::Bool);
  p.setList("nodes", {"risk", "tracker"});
  EXPECT_DOUBLE_EQ(p.getDouble("rate", 0.0), 30.0);  // an integer is a valid double
  EXPECT_EQ(p.getInt("rate", 0), 30);
  EXPECT_THROW(p.getInt("gain", 0), std::invalid_argument);  // a double is not an integer
  EXPECT_THROW(p.getDouble("flag", 0.0), std::invalid_argument);
  EXPECT_THROW(p.getString("name", ""), std::invalid_argument);
  EXPECT_EQ(p.getStringList("nodes", {}), (std::vector<std::string>{"risk", "tracker"}));
  EXPECT_THROW(p.getStringList("rate", {}), std::invalid_argument);
  try {
    p.getBool("pretty", true);  // 1 is not a boolean on the parameter server
    FAIL() << "an integer was read as a boolean";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'/pe/pretty' has the wrong type"), std::string::npos) << e.what();
  }
  // Text (YAML) parses as any scalar, but is not a list.
  ParamMap t({{"pretty", "1"}, {"nodes", "risk"}});
  EXPECT_TRUE(t.getBool("pretty", false));
  EXPECT_THROW(t.getStringList("nodes", {}), std::invalid_argument);
}

TEST(ParamMap, SubMergeAndSkippedSubtrees) {
  ParamMap p;
  p.setLabel("/plan/");
  p.set("aco/ants", "10", asv::ParamType::Int);
  p.set("aco/rho", "x", asv::ParamType::String);
  p.set("exchange/topic", "/i", asv::ParamType::String);
  p.set("seed", "1", asv::ParamType::Int);
  const ParamMap aco = p.sub("aco");
  EXPECT_EQ(aco.fullName("ants"), "/plan/aco/ants");
  EXPECT_THROW(aco.getDouble("rho", 0.1), std::invalid_argument);  // the type came along
  ParamMap base({{"ants", "5"}, {"alpha", "1"}});
  base.merge(aco);
  EXPECT_EQ(base.getInt("ants", 0), 10);  // the node's value over the scenario's
  EXPECT_EQ(base.getInt("alpha", 0), 1);
  p.getInt("seed", 0);
  EXPECT_EQ(p.unknownKeys({"aco/", "exchange/"}), std::vector<std::string>{});
  EXPECT_EQ(p.unknownKeys({"aco/"}), std::vector<std::string>{"exchange/topic"});
  EXPECT_EQ(p.getSize("seed", 0, 1), 1u);
  ParamMap neg;
  neg.set("n", "-1", asv::ParamType::Int);
  EXPECT_THROW(neg.getSize("n", 0), std::invalid_argument);
}
