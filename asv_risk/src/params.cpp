#include "asv_risk/params.h"

#include <stdexcept>

#include "asv_core/world/scenario.h"

namespace asv_risk {

void resolveOrigin(asv::IngestionConfig& c) {
  if (c.origin_scenario.empty())
    return;
  const asv::Scenario s = asv::loadScenario(
      c.origin_scenario, asv::ChartOptions{"", "", false});  // throws naming the file, line and key
  if (!s.has_origin)
    throw std::invalid_argument("origin_scenario '" + c.origin_scenario + "' has no origin");
  c.origin_lat_deg = s.origin.lat_deg;
  c.origin_lon_deg = s.origin.lon_deg;
  c.has_origin = true;
}

}  // namespace asv_risk
