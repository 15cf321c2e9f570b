// Land from charts: a GeoJSON island (fixture), a shapefile the test writes, GSHHG round New York,
// the cache, and the scenario's charts key. Expected positions are computed by hand from the WGS84
// meridian and parallel arc lengths (not through GeographicLib, which the code uses).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <ogrsf_frmts.h>

#include "asv_core/charts/charts.h"
#include "asv_core/world/scenario.h"

namespace {

using asv::ChartError;
using asv::ChartSpec;
using asv::LocalFrame;
using asv::Polygon;
using Eigen::Vector2d;

const std::string kIsland = std::string(ASV_SOURCE_DIR) + "/src/test/data/island.geojson";

// Metres per degree of latitude and of longitude at latitude `lat` on WGS84 (textbook formulas).
double meridianDegree(double lat) {
  const double a = 6378137.0, f = 1 / 298.257223563, e2 = f * (2 - f), s = std::sin(lat * M_PI / 180);
  return a * (1 - e2) / std::pow(1 - e2 * s * s, 1.5) * M_PI / 180;
}
double parallelDegree(double lat) {
  const double a = 6378137.0, f = 1 / 298.257223563, e2 = f * (2 - f), s = std::sin(lat * M_PI / 180);
  return a / std::sqrt(1 - e2 * s * s) * std::cos(lat * M_PI / 180) * M_PI / 180;
}

bool onLand(const std::vector<Polygon>& land, const Vector2d& p) {
  for (const auto& poly : land)
    if (asv::pointInPolygon(poly, p))
      return true;
  return false;
}

std::string tempDir(const std::string& name) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("asv_test_charts_" + name + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

ChartSpec fileSpec(const std::string& source) {
  ChartSpec s;
  s.source = source;
  s.radius_m = 5000;
  s.simplify_m = 0;
  return s;
}

const LocalFrame kGdansk(54.60, 18.80);

TEST(Charts, GeoJsonIslandIsWhereTheArcLengthsPutIt) {
  const auto land = asv::loadChartLand(fileSpec(kIsland), kGdansk, Vector2d::Zero());
  ASSERT_EQ(land.size(), 2u);  // the island and the islet; the line string is not land
  // The island's south-west corner (54.61 N, 18.82 E): 0.01 deg of meridian north, 0.02 deg of the
  // parallel east (the parallel's curvature below the tangent plane is 0.2 m at this distance).
  const double y = 0.5 * (meridianDegree(54.60) + meridianDegree(54.61)) * 0.01;
  const double x = parallelDegree(54.61) * 0.02;
  const Eigen::AlignedBox2d box = asv::boundingBox(land[0]);
  EXPECT_NEAR(box.min().x(), x, 1.0);
  EXPECT_NEAR(box.min().y(), y, 1.0);
  EXPECT_NEAR(box.max().y(), 2 * y, 2.0);
  // The islet, 0.01 deg south and 0.02 deg west.
  const Eigen::AlignedBox2d islet = asv::boundingBox(land[1]);
  EXPECT_NEAR(islet.min().x(), -parallelDegree(54.59) * 0.02, 1.0);
  EXPECT_NEAR(islet.min().y(), -0.5 * (meridianDegree(54.60) + meridianDegree(54.59)) * 0.01, 1.0);
}

TEST(Charts, UnreachableLakeIsLandAndTheShipsLakeIsWater) {
  // The lake (54.613-54.617 N, 18.825-18.835 E) inside the island; its middle, by hand:
  const Vector2d lake(parallelDegree(54.615) * 0.03,
                      0.5 * (meridianDegree(54.60) + meridianDegree(54.615)) * 0.015);
  const Vector2d shore(parallelDegree(54.611) * 0.021,
                       0.5 * (meridianDegree(54.60) + meridianDegree(54.611)) * 0.011);
  const auto from_sea = asv::loadChartLand(fileSpec(kIsland), kGdansk, Vector2d::Zero());
  EXPECT_TRUE(onLand(from_sea, lake));  // a ship at sea cannot reach the lake: it is land to her
  EXPECT_TRUE(onLand(from_sea, shore));
  const auto from_lake = asv::loadChartLand(fileSpec(kIsland), kGdansk, lake);
  EXPECT_FALSE(onLand(from_lake, lake));  // a ship on the lake: the lake is water, its shore land
  EXPECT_TRUE(onLand(from_lake, shore));
  EXPECT_FALSE(onLand(from_lake, Vector2d::Zero()));
  EXPECT_FALSE(onLand(from_lake, lake + Vector2d(250, 100)));  // elsewhere in the lake
}

TEST(Charts, ClipsToTheSquare) {
  ChartSpec s = fileSpec(kIsland);
  s.radius_m = 1800;  // cuts the island (x 1292..2585 m, y 1113..2226 m) at x = y = 1800 m
  const auto land = asv::loadChartLand(s, kGdansk, Vector2d::Zero());
  ASSERT_EQ(land.size(), 2u);
  const Eigen::AlignedBox2d box = asv::boundingBox(land[0]);
  EXPECT_NEAR(box.max().x(), 1800.0, 1e-6);
  EXPECT_NEAR(box.max().y(), 1800.0, 1e-6);
}

// Writes a one-polygon shapefile through OGR, in UTM zone 34N (EPSG:32634), so the test also covers
// the conversion of a projected chart to WGS84.
std::string writeShapefile(const std::string& dir, const std::string& layer_name) {
  GDALAllRegister();
  GDALDriver* drv = GetGDALDriverManager()->GetDriverByName("ESRI Shapefile");
  std::string path = dir + "/land.shp";
  GDALDataset* ds = drv->Create(path.c_str(), 0, 0, 0, GDT_Unknown, nullptr);
  OGRSpatialReference utm, wgs;
  utm.importFromEPSG(32634);
  wgs.SetWellKnownGeogCS("WGS84");
  utm.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  wgs.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  OGRLayer* layer = ds->CreateLayer(layer_name.c_str(), &utm, wkbPolygon, nullptr);
  OGRLinearRing ring;
  for (const auto& [lon, lat] : {std::pair{18.82, 54.61}, {18.84, 54.61}, {18.84, 54.62}, {18.82, 54.62}})
    ring.addPoint(lon, lat);
  ring.closeRings();
  OGRPolygon poly;
  poly.addRing(&ring);
  std::unique_ptr<OGRCoordinateTransformation> t(OGRCreateCoordinateTransformation(&wgs, &utm));
  poly.transform(t.get());
  OGRFeature* f = OGRFeature::CreateFeature(layer->GetLayerDefn());
  f->SetGeometry(&poly);
  EXPECT_EQ(layer->CreateFeature(f), OGRERR_NONE);
  OGRFeature::DestroyFeature(f);
  GDALClose(ds);
  return path;
}

TEST(Charts, ShapefileInUtmComesBackInTheLocalFrame) {
  const std::string path = writeShapefile(tempDir("shp"), "land");
  const auto land = asv::loadChartLand(fileSpec(path), kGdansk, Vector2d::Zero());
  ASSERT_EQ(land.size(), 1u);
  const Eigen::AlignedBox2d box = asv::boundingBox(land[0]);
  EXPECT_NEAR(box.min().y(), 0.5 * (meridianDegree(54.60) + meridianDegree(54.61)) * 0.01, 1.0);
  EXPECT_NEAR(box.min().x(), parallelDegree(54.61) * 0.02, 1.0);
}

TEST(Charts, ErrorsNameTheSourceAndTheLayers) {
  const std::string path = writeShapefile(tempDir("layers"), "land");
  ChartSpec s = fileSpec(path);
  s.layer = "LNDARE";
  try {
    asv::loadChartLand(s, kGdansk, Vector2d::Zero());
    FAIL() << "a missing layer was accepted";
  } catch (const ChartError& e) {
    EXPECT_NE(std::string(e.what()).find("no layer 'LNDARE' (layers: land)"), std::string::npos) << e.what();
  }
  try {
    asv::loadChartLand(fileSpec("/nonexistent/chart.geojson"), kGdansk, Vector2d::Zero());
    FAIL() << "a missing file was accepted";
  } catch (const ChartError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/chart.geojson: cannot open"), std::string::npos)
        << e.what();
  }
  ChartSpec g;
  g.source = "gshhg";
  g.resolution = "medium";
  EXPECT_THROW(asv::loadChartLand(g, kGdansk, Vector2d::Zero()), ChartError);
}

TEST(Charts, CacheGivesTheSameLandBitForBitAndIgnoresAStaleFile) {
  ChartSpec s = fileSpec(kIsland);
  s.cache_dir = tempDir("cache");
  s.simplify_m = 10;
  const std::string path = asv::chartCachePath(s, kGdansk, Vector2d::Zero());
  ASSERT_FALSE(std::filesystem::exists(path));
  const auto fresh = asv::loadChartLand(s, kGdansk, Vector2d::Zero());
  ASSERT_TRUE(std::filesystem::exists(path));
  const auto cached = asv::loadChartLand(s, kGdansk, Vector2d::Zero());
  EXPECT_EQ(fresh, cached);
  // A cache file of other settings (its first line is the key) is not used.
  { std::ofstream(path) << "# some other key\npolygon 3\n0 0\n1 0\n0 1\n"; }
  EXPECT_EQ(asv::loadChartLand(s, kGdansk, Vector2d::Zero()), fresh);
  // Another area is another file.
  EXPECT_NE(asv::chartCachePath(s, LocalFrame(54.6, 18.81), Vector2d::Zero()), path);
}

// GSHHG full round the Upper Bay of New York Harbor (gmt and gmt-gshhg-full from scripts/setup).
std::vector<Polygon> newYork(const LocalFrame& frame) {
  ChartSpec s;
  s.source = "gshhg";
  s.radius_m = 15000;
  return asv::loadChartLand(s, frame, Vector2d::Zero());
}

TEST(Charts, GshhgNewYorkManhattanAndStatenIslandAreLandTheUpperBayWater) {
  const LocalFrame ny(40.66, -74.05);  // the Upper Bay, between Bayonne and Brooklyn
  const auto land = newYork(ny);
  ASSERT_FALSE(land.empty());
  EXPECT_TRUE(onLand(land, ny.toLocal(40.7829, -73.9654)));   // Central Park, Manhattan
  EXPECT_TRUE(onLand(land, ny.toLocal(40.7061, -74.0087)));   // Wall Street, Manhattan
  EXPECT_TRUE(onLand(land, ny.toLocal(40.5795, -74.1502)));   // Staten Island
  EXPECT_TRUE(onLand(land, ny.toLocal(40.6782, -73.9442)));   // Brooklyn
  EXPECT_FALSE(onLand(land, ny.toLocal(40.6700, -74.0500)));  // Upper Bay
  EXPECT_FALSE(onLand(land, ny.toLocal(40.7400, -74.0150)));  // Hudson River off Hoboken
  EXPECT_FALSE(onLand(land, ny.toLocal(40.6800, -74.0350)));  // between Liberty and Governors Islands
  EXPECT_FALSE(onLand(land, ny.toLocal(40.5500, -74.0300)));  // Lower Bay
  EXPECT_TRUE(onLand(land, ny.toLocal(40.6892, -74.0445)));   // Liberty Island itself
  // rviz draws land filled: every polygon's triangles cover exactly its area (shoelace formula).
  for (const Polygon& p : land) {
    double area2 = 0.0, tri2 = 0.0;
    for (size_t i = 0, j = p.size() - 1; i < p.size(); j = i++)
      area2 += asv::cross2(p[j], p[i]);
    for (const auto& t : asv::triangulate(p))
      tri2 += std::fabs(asv::cross2(p[t[1]] - p[t[0]], p[t[2]] - p[t[0]]));
    EXPECT_NEAR(tri2, std::fabs(area2), 1e-6 * std::fabs(area2)) << p.size() << " vertices";
  }
}

// The real New York AIS hour: ships under way (SOG >= 5 kn) are afloat. GSHHG's shoreline comes from
// the World Vector Shoreline (1:250,000; 90 % of it within 500 m of the true shore), which draws piers
// and narrow rivers as land: a report may fall on GSHHG land, but 99 % must be afloat or within 500 m
// of its shore. The square is 9 km round the Upper Bay: GSHHG closes the Hudson at 40.77 N. (Measured:
// 107 of 885 reports on land, median 43 m in, 3 deeper than 500 m.) Skips without the data.
TEST(Charts, GshhgNewYorkShipsUnderWayAreAfloatToTheShorelinesAccuracy) {
  const std::string csv = std::string(ASV_SHARED_DIR) + "/data/ais/real/NYHarbor_2020_06_30_first_hour.csv";
  std::ifstream f(csv);
  if (!f)
    GTEST_SKIP() << "the New York AIS file is not present (" << csv << ")";
  const LocalFrame ny(40.66, -74.05);
  const auto land = newYork(ny);
  std::string line;
  std::getline(f, line);
  int total = 0, on_land = 0, deep = 0;
  while (std::getline(f, line)) {
    std::stringstream ss(line);
    std::string time, lon, lat, mmsi, sog;
    std::getline(ss, time, ','), std::getline(ss, lon, ','), std::getline(ss, lat, ',');
    std::getline(ss, mmsi, ','), std::getline(ss, sog, ',');
    const Vector2d p = ny.toLocal(std::stod(lat), std::stod(lon));
    if (std::stod(sog) < 5.0 || std::abs(p.x()) > 9000 || std::abs(p.y()) > 9000)
      continue;
    ++total;
    for (const auto& poly : land) {
      if (asv::pointInPolygon(poly, p)) {
        ++on_land;
        deep += asv::segmentPolygonDistance(poly, p, p) > 500.0 ? 1 : 0;
      }
    }
  }
  std::printf("%d of %d reports of ships under way on GSHHG land, %d more than 500 m in\n", on_land, total,
              deep);
  ASSERT_GT(total, 500);
  EXPECT_LT(on_land, total / 5);
  EXPECT_LE(deep, total / 100);
}

TEST(Charts, ScenarioChartsKeyLoadsLandWithTheClearance) {
  const std::string dir = tempDir("scenario");
  std::filesystem::copy_file(kIsland, dir + "/island.geojson");
  const std::string yaml = R"(format: 1
name: chart island
duration_s: 600
origin: {lat_deg: 54.60, lon_deg: 18.80}
charts: {source: island.geojson, radius_m: 5000, simplify_m: 0, clearance_m: 150}
own_ship: {name: own, position: {x_m: 0, y_m: 0}, course_deg: 45, speed_mps: 5, goal: {x_m: 4000, y_m: 4000}}
)";
  std::ofstream(dir + "/s.yaml") << yaml;
  asv::ChartOptions o;
  o.cache_dir = "none";
  const asv::Scenario s = asv::loadScenario(dir + "/s.yaml", o);
  ASSERT_EQ(s.obstacles.size(), 2u);
  EXPECT_EQ(s.obstacles[0].name, "land 1");
  EXPECT_DOUBLE_EQ(s.min_obstacle_clearance, 150.0);
  // parseScenario alone reads the key but loads nothing.
  EXPECT_TRUE(asv::parseScenario(yaml, dir + "/s.yaml").obstacles.empty());
}

TEST(Charts, ScenarioChartsKeyErrors) {
  const std::string head = "format: 1\nname: x\nduration_s: 600\n";
  const std::string own = "own_ship: {name: own, position: {x_m: 0, y_m: 0}, course_deg: 0, speed_mps: 5}\n";
  auto error = [&](const std::string& body) {
    try {
      asv::parseScenario(head + body + own, "s.yaml");
    } catch (const asv::ScenarioError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(error("charts: {source: gshhg}\n").find("need the scenario's origin"), std::string::npos);
  const std::string origin = "origin: {lat_deg: 54.6, lon_deg: 18.8}\n";
  EXPECT_NE(
      error(origin + "charts: {source: gshhg, resolution: medium}\n").find("s.yaml:5: 'charts.resolution'"),
      std::string::npos);
  EXPECT_NE(error(origin + "charts: {source: gshhg, radius: 3}\n").find("'charts.radius': unknown key"),
            std::string::npos);
  EXPECT_NE(
      error(origin + "safety: {min_obstacle_clearance_m: 100}\ncharts: {source: gshhg, clearance_m: 150}\n")
          .find("given under safety already"),
      std::string::npos);
}

TEST(Charts, OwnShipOnLandIsAnError) {
  const std::string yaml =
      "format: 1\nname: x\nduration_s: 600\norigin: {lat_deg: 54.6, lon_deg: 18.8}\n"
      "charts: {source: " +
      kIsland +
      ", radius_m: 5000}\n"
      "own_ship: {name: own, position: {x_m: 1500, y_m: 1300}, course_deg: 0, speed_mps: 5}\n";
  asv::Scenario s = asv::parseScenario(yaml, "s.yaml");
  asv::ChartOptions o;
  o.cache_dir = "none";
  try {
    asv::loadCharts(s, o);
    FAIL() << "a ship on land was accepted";
  } catch (const asv::ScenarioError& e) {
    EXPECT_NE(std::string(e.what()).find("s.yaml: 'charts': the own ship starts on land"), std::string::npos)
        << e.what();
  }
}

}  // namespace
