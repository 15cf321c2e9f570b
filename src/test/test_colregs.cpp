#include <gtest/gtest.h>

#include "asv_core/risk/colregs.h"

using namespace asv;

namespace {
ShipState ship(double x, double y, double course_deg, double speed) {
  ShipState s;
  s.position = {x, y};
  s.course = s.heading = degToRad(course_deg);
  s.speed = speed;
  return s;
}
EncounterGeometry classify(const ShipState& own, const ShipState& tgt) {
  return classifyEncounter(own, tgt, computeCpa(own, tgt), ColregsConfig{});
}
}  // namespace

TEST(Colregs, RelativeBearingAndAspect) {
  const ShipState own = ship(0, 0, 90, 5);                             // heading east
  EXPECT_NEAR(radToDeg(relativeBearing(own, {0, 100})), 270.0, 1e-9);  // north is on the port beam
  EXPECT_NEAR(radToDeg(relativeBearing(own, {0, -100})), 90.0, 1e-9);  // south is on the starboard beam
  const EncounterGeometry g = classify(ship(0, 0, 0, 5), ship(1000, 1000, 270, 5));
  EXPECT_NEAR(radToDeg(g.relative_bearing), 45.0, 1e-9);
  EXPECT_NEAR(radToDeg(g.aspect), 315.0, 1e-9);  // the target sees us 45 deg on its port bow
}

TEST(Colregs, HeadOn) {
  EncounterGeometry g = classify(ship(0, 0, 0, 5), ship(0, 5000, 180, 5));
  EXPECT_EQ(g.encounter, Encounter::HeadOn);
  EXPECT_EQ(g.role, OwnRole::BothGiveWay);
  EXPECT_EQ(applicableRule(g.encounter), 14);
  // Nearly reciprocal: 10 deg off on both sides is still head-on, 20 deg is a crossing.
  g = classify(ship(0, 0, 0, 5), ship(500, 5000, 190, 5));
  EXPECT_EQ(g.encounter, Encounter::HeadOn);
  // Fine on the starboard bow (5.7 deg) but seeing us 29 deg on its port bow: a crossing, not head-on.
  g = classify(ship(0, 0, 0, 5), ship(500, 5000, 215, 5));
  EXPECT_EQ(g.encounter, Encounter::CrossingGiveWay);
}

TEST(Colregs, CrossingFromStarboardIsGiveWay) {
  const EncounterGeometry g = classify(ship(0, 0, 0, 5), ship(1000, 1000, 270, 5));
  EXPECT_EQ(g.encounter, Encounter::CrossingGiveWay);
  EXPECT_EQ(g.role, OwnRole::GiveWay);
  EXPECT_EQ(applicableRule(g.encounter), 15);
}

TEST(Colregs, CrossingFromPortIsStandOn) {
  const EncounterGeometry g = classify(ship(0, 0, 0, 5), ship(-1000, 1000, 90, 5));
  EXPECT_EQ(g.encounter, Encounter::CrossingStandOn);
  EXPECT_EQ(g.role, OwnRole::StandOn);
  EXPECT_EQ(applicableRule(g.encounter), 17);
}

TEST(Colregs, OvertakingAndBeingOvertaken) {
  EncounterGeometry g = classify(ship(0, 0, 0, 10), ship(100, 2000, 10, 4));
  EXPECT_EQ(g.encounter, Encounter::Overtaking);
  EXPECT_EQ(g.role, OwnRole::GiveWay);
  EXPECT_EQ(applicableRule(g.encounter), 13);
  g = classify(ship(0, 0, 0, 4), ship(-100, -2000, 0, 10));
  EXPECT_EQ(g.encounter, Encounter::BeingOvertaken);
  EXPECT_EQ(g.role, OwnRole::StandOn);
  // A target 30 deg abaft the starboard beam (relative 120 deg) closing fast is overtaking us.
  const ShipState own = ship(0, 0, 0, 3);
  const Eigen::Vector2d p = 2000 * Eigen::Vector2d(std::sin(degToRad(120)), std::cos(degToRad(120)));
  g = classify(own, ship(p.x(), p.y(), 340, 12));
  EXPECT_EQ(g.encounter, Encounter::BeingOvertaken);
}

TEST(Colregs, NoEncounterWhenSafe) {
  // Diverging, parallel at the same speed, out of range.
  EXPECT_EQ(classify(ship(0, 0, 0, 5), ship(0, -1000, 180, 5)).encounter, Encounter::None);
  EXPECT_EQ(classify(ship(0, 0, 0, 5), ship(500, 0, 0, 5)).encounter, Encounter::None);
  EXPECT_EQ(classify(ship(0, 0, 0, 5), ship(0, 30000, 180, 5)).encounter, Encounter::None);
  ColregsConfig bad;
  bad.stern_sector_start_deg = 200;
  EXPECT_THROW(bad.validate(), std::invalid_argument);
}
