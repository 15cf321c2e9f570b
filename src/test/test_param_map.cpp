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
