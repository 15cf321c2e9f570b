// Target.quality values set by the ingestion nodes (asv_msgs/Target has no flag for an unknown
// velocity, so the quality carries it; the tracker relies on these).
#pragma once

#include <cstdint>

namespace asv_risk {

constexpr std::uint8_t kQualityFull = 100;              // position, course and speed over ground reported
constexpr std::uint8_t kQualityCourseFromHeading = 70;  // COG not available: the true heading stands in
constexpr std::uint8_t kQualityArpa = 80;               // radar target tracking (TTM status T)
constexpr std::uint8_t kQualityAcquiring = 50;          // radar target being acquired (status Q)
// Velocity unknown: speed_over_ground, course_over_ground and velocity are 0 and mean nothing.
// Any quality at or below this value says so.
constexpr std::uint8_t kQualityNoVelocity = 40;

inline bool hasVelocity(std::uint8_t quality) {
  return quality > kQualityNoVelocity;
}

}  // namespace asv_risk
