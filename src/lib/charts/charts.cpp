// Land from charts (charts.h): read (GSHHG or an OGR file), clip to the area in lon/lat, project to the
// scenario's ENU frame, clip to the square, simplify, resolve holes, cache.
#include "asv_core/charts/charts.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

#include <cpl_error.h>
#include <gdal_priv.h>
#include <ogrsf_frmts.h>

#include "ogr_land.h"

namespace asv {
namespace charts_detail {

LonLatBox geoBox(const LocalFrame& frame, double half_side_m) {
  const double r = half_side_m * 1.05;  // a margin: the square's edges are not lines of latitude
  LonLatBox b{1e9, -1e9, 1e9, -1e9};
  for (int i = -2; i <= 2; ++i) {
    for (int j = -2; j <= 2; ++j) {
      const GeoPoint g = frame.toGeodetic(Eigen::Vector2d(r * i / 2.0, r * j / 2.0));
      b.west = std::min(b.west, g.lon_deg), b.east = std::max(b.east, g.lon_deg);
      b.south = std::min(b.south, g.lat_deg), b.north = std::max(b.north, g.lat_deg);
    }
  }
  // On a 1e-6 deg grid, outwards: GMT is given the box as text and must cut its pieces on exactly
  // the outline the polygoniser closes them with.
  // (n / 1e7 for integer n: the shoreline points are snapped to the same form.)
  b.west = std::floor(b.west * 1e6) * 10 / 1e7, b.south = std::floor(b.south * 1e6) * 10 / 1e7;
  b.east = std::ceil(b.east * 1e6) * 10 / 1e7, b.north = std::ceil(b.north * 1e6) * 10 / 1e7;
  return b;
}

GeomPtr boxPolygon(const LonLatBox& b) {
  OGRLinearRing ring;
  ring.addPoint(b.west, b.south);
  ring.addPoint(b.east, b.south);
  ring.addPoint(b.east, b.north);
  ring.addPoint(b.west, b.north);
  ring.closeRings();
  auto poly = std::make_unique<OGRPolygon>();
  poly->addRing(&ring);
  return GeomPtr(poly.release());
}

}  // namespace charts_detail

namespace {

using charts_detail::GeomPtr;
using charts_detail::LonLatBox;

GeomPtr localSquare(double r) {
  return charts_detail::boxPolygon(LonLatBox{-r, r, -r, r});
}

bool isS57(GDALDataset& ds) {
  return ds.GetDriver() && std::string(ds.GetDriver()->GetDescription()) == "S57";
}

// The layers of a chart file that hold land.
std::vector<OGRLayer*> landLayers(GDALDataset& ds, const ChartSpec& spec) {
  const std::string name = !spec.layer.empty() ? spec.layer : (isS57(ds) ? "LNDARE" : "");
  std::vector<OGRLayer*> layers;
  if (name.empty()) {
    for (OGRLayer* l : ds.GetLayers())
      layers.push_back(l);
    return layers;
  }
  if (OGRLayer* l = ds.GetLayerByName(name.c_str()))
    return {l};
  std::string known;
  for (OGRLayer* l : ds.GetLayers())
    known += std::string(known.empty() ? "" : ", ") + l->GetName();
  throw ChartError(spec.source + ": no layer '" + name + "' (layers: " + (known.empty() ? "none" : known) +
                   ")");
}

// Adds the polygons of `g` (a polygon, multipolygon or collection) to `out`, made valid.
void collectPolygons(const OGRGeometry* g, std::vector<GeomPtr>& out) {
  if (!g || g->IsEmpty())
    return;
  const auto type = wkbFlatten(g->getGeometryType());
  if (type == wkbPolygon) {
    GeomPtr p(g->clone());
    if (!p->IsValid())
      p.reset(p->MakeValid());
    if (p && wkbFlatten(p->getGeometryType()) != wkbPolygon) {
      collectPolygons(p.get(), out);  // made valid into several parts
      return;
    }
    if (p)
      out.push_back(std::move(p));
  } else if (type == wkbMultiPolygon || type == wkbGeometryCollection) {
    for (const OGRGeometry* part : *g->toGeometryCollection())
      collectPolygons(part, out);
  }
}

// Land polygons (lon/lat) of an OGR vector source within `box`; other geometry types are skipped.
std::vector<GeomPtr> readFileLand(const ChartSpec& spec, const LonLatBox& box) {
  GDALAllRegister();
  CPLErrorReset();
  GDALDatasetUniquePtr ds(GDALDataset::Open(spec.source.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY));
  if (!ds)
    throw ChartError(spec.source + ": cannot open as a vector chart (" +
                     (CPLGetLastErrorMsg()[0] ? CPLGetLastErrorMsg() : "no such file or unknown format") +
                     ")");
  OGRSpatialReference wgs84;
  wgs84.SetWellKnownGeogCS("WGS84");
  wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  std::vector<GeomPtr> polys;
  for (OGRLayer* layer : landLayers(*ds, spec)) {
    std::unique_ptr<OGRCoordinateTransformation> to_wgs84;
    const OGRSpatialReference* srs = layer->GetSpatialRef();
    if (srs && !srs->IsSame(&wgs84)) {
      to_wgs84.reset(OGRCreateCoordinateTransformation(srs, &wgs84));
      if (!to_wgs84)
        throw ChartError(spec.source + ": layer " + layer->GetName() +
                         " has a CRS GDAL cannot convert to WGS84");
    } else {
      layer->SetSpatialFilterRect(box.west, box.south, box.east, box.north);
    }
    layer->ResetReading();
    for (auto& feature : *layer) {
      const OGRGeometry* g = feature->GetGeometryRef();
      if (!g)
        continue;
      GeomPtr copy(g->clone());
      if (to_wgs84 && copy->transform(to_wgs84.get()) != OGRERR_NONE)
        throw ChartError(spec.source + ": a feature of layer " + layer->GetName() +
                         " cannot be converted to WGS84");
      collectPolygons(copy.get(), polys);
    }
  }
  return polys;
}

// Every vertex of `g` from lon/lat to the local ENU frame.
void project(OGRGeometry& g, const LocalFrame& frame) {
  const auto type = wkbFlatten(g.getGeometryType());
  if (type == wkbPolygon) {
    for (OGRLinearRing* ring : *g.toPolygon()) {
      for (int i = 0; i < ring->getNumPoints(); ++i) {
        const Eigen::Vector2d p = frame.toLocal(ring->getY(i), ring->getX(i));
        ring->setPoint(i, p.x(), p.y());
      }
    }
  } else if (type == wkbMultiPolygon || type == wkbGeometryCollection) {
    for (OGRGeometry* part : *g.toGeometryCollection())
      project(*part, frame);
  }
}

Polygon ringToPolygon(const OGRLinearRing& ring) {
  Polygon p;
  const int n = ring.getNumPoints();
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d v(ring.getX(i), ring.getY(i));
    if (p.empty() || v != p.back())
      p.push_back(v);
  }
  if (p.size() > 1 && p.front() == p.back())
    p.pop_back();
  return p;
}

bool crossesRing(const Polygon& ring, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  for (size_t i = 0; i < ring.size(); ++i) {
    const Eigen::Vector2d& c = ring[i];
    const Eigen::Vector2d& d = ring[(i + 1) % ring.size()];
    if (c == a || d == a || c == b || d == b)
      continue;  // the bridge's own end vertices
    if (segmentsIntersect(a, b, c, d))
      return true;
  }
  return false;
}

// `outer` with `hole` joined to it along a bridge that crosses neither ring: one ring whose crossing
// rule finds the hole outside. The bridge is the shortest clear one from a hole vertex.
Polygon keyhole(const Polygon& outer, const Polygon& hole) {
  std::vector<std::pair<double, std::pair<size_t, size_t>>> bridges;
  for (size_t h = 0; h < hole.size(); ++h) {
    size_t best = 0;
    for (size_t o = 1; o < outer.size(); ++o)
      if ((outer[o] - hole[h]).squaredNorm() < (outer[best] - hole[h]).squaredNorm())
        best = o;
    bridges.push_back({(outer[best] - hole[h]).squaredNorm(), {best, h}});
  }
  std::sort(bridges.begin(), bridges.end());
  for (const auto& [d2, ends] : bridges) {
    const auto [o, h] = ends;
    if (crossesRing(outer, outer[o], hole[h]) || crossesRing(hole, outer[o], hole[h]))
      continue;
    Polygon joined(outer.begin(), outer.begin() + static_cast<long>(o) + 1);
    for (size_t k = 0; k <= hole.size(); ++k)
      joined.push_back(hole[(h + k) % hole.size()]);
    joined.insert(joined.end(), outer.begin() + static_cast<long>(o), outer.end());
    return joined;
  }
  throw ChartError("charts: no clear bridge from the lake round the own ship to its shore");
}

// A land polygon as simple polygons: holes the ship cannot reach are filled; the one it is in is
// joined to the outline (charts.h).
Polygon resolveHoles(const OGRPolygon& p, const Eigen::Vector2d& water) {
  Polygon outer = ringToPolygon(*p.getExteriorRing());
  for (int i = 0; i < p.getNumInteriorRings(); ++i) {
    const Polygon hole = ringToPolygon(*p.getInteriorRing(i));
    if (hole.size() >= 3 && pointInPolygon(hole, water))
      return keyhole(outer, hole);
  }
  return outer;
}

// One lon/lat land polygon to local simple polygons within the square.
void addLocal(const OGRGeometry& ll, const ChartSpec& spec, const LocalFrame& frame,
              const OGRGeometry& box_ll, const Eigen::Vector2d& water, std::vector<Polygon>& out) {
  GeomPtr clipped(ll.Intersection(&box_ll));
  if (!clipped || clipped->IsEmpty())
    return;
  project(*clipped, frame);
  const GeomPtr square = localSquare(spec.radius_m);
  GeomPtr local(clipped->Intersection(square.get()));
  if (local && spec.simplify_m > 0.0)
    local.reset(local->SimplifyPreserveTopology(spec.simplify_m));
  std::vector<GeomPtr> parts;
  collectPolygons(local.get(), parts);
  for (const GeomPtr& part : parts) {
    Polygon p = resolveHoles(*part->toPolygon(), water);
    if (p.size() >= 3)
      out.push_back(std::move(p));
  }
}

uint64_t fnv1a(const std::string& s) {
  uint64_t h = 1469598103934665603ULL;
  for (const unsigned char c : s)
    h = (h ^ c) * 1099511628211ULL;
  return h;
}

// Everything an extraction depends on, as text: the cache key.
std::string cacheKey(const ChartSpec& spec, const LocalFrame& frame, const Eigen::Vector2d& water) {
  std::ostringstream k;
  k.precision(17);
  k << "asv-chart-land-v1|" << spec.source << '|';
  std::error_code ec;
  if (spec.source != "gshhg" && std::filesystem::exists(spec.source, ec)) {
    k << std::filesystem::file_size(spec.source, ec) << '|'
      << std::filesystem::last_write_time(spec.source, ec).time_since_epoch().count() << '|';
  }
  k << spec.resolution << '|' << spec.layer << '|' << spec.radius_m << '|' << spec.simplify_m << '|'
    << frame.origin().lat_deg << '|' << frame.origin().lon_deg << '|' << water.x() << '|' << water.y();
  return k.str();
}

bool readCache(const std::string& path, const std::string& key, std::vector<Polygon>& land) {
  std::ifstream f(path);
  std::string header;
  if (!f || !std::getline(f, header) || header != "# " + key)
    return false;
  land.clear();
  std::string word;
  size_t n = 0;
  while (f >> word >> n) {
    if (word != "polygon" || n > 10000000)
      return false;
    Polygon p(n);
    for (auto& v : p)
      if (!(f >> v.x() >> v.y()))
        return false;
    land.push_back(std::move(p));
  }
  return f.eof();
}

void writeCache(const std::string& path, const std::string& key, const std::vector<Polygon>& land) {
  std::error_code ec;
  std::filesystem::create_directories(std::filesystem::path(path).parent_path(), ec);
  const std::string tmp = path + ".tmp" + std::to_string(::getpid());
  {
    std::ofstream f(tmp);
    if (!f)
      return;  // a cache that cannot be written only costs time
    f.precision(17);
    f << "# " << key << '\n';
    for (const Polygon& p : land) {
      f << "polygon " << p.size() << '\n';
      for (const auto& v : p)
        f << v.x() << ' ' << v.y() << '\n';
    }
  }
  std::filesystem::rename(tmp, path, ec);
}

std::vector<Polygon> extract(const ChartSpec& spec, const LocalFrame& frame, const Eigen::Vector2d& water) {
  const LonLatBox box = charts_detail::geoBox(frame, spec.radius_m);
  const std::vector<GeomPtr> land_ll =
      spec.source == "gshhg" ? charts_detail::readGshhgLand(gshhgResolutionCode(spec.resolution), box)
                             : readFileLand(spec, box);
  const GeomPtr box_ll = charts_detail::boxPolygon(box);
  std::vector<Polygon> land;
  for (const GeomPtr& g : land_ll)
    addLocal(*g, spec, frame, *box_ll, water, land);
  return land;
}

}  // namespace

ChartOptions ChartOptions::fromParams(const ParamMap& params) {
  ChartOptions o;
  o.source = params.getString("charts", o.source);
  o.cache_dir = params.getString("chart_cache_dir", o.cache_dir);
  return o;
}

std::string defaultChartCacheDir() {
  if (const char* d = std::getenv("ASV_CHART_CACHE"); d && *d)
    return d;
  if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x)
    return std::string(x) + "/asv/charts";
  if (const char* h = std::getenv("HOME"); h && *h)
    return std::string(h) + "/.cache/asv/charts";
  return "";
}

std::string chartCachePath(const ChartSpec& spec, const LocalFrame& frame, const Eigen::Vector2d& water) {
  if (spec.cache_dir.empty())
    return "";
  char name[40];
  std::snprintf(name, sizeof name, "land-%016llx.txt",
                static_cast<unsigned long long>(fnv1a(cacheKey(spec, frame, water))));
  return spec.cache_dir + "/" + name;
}

std::vector<Polygon> loadChartLand(const ChartSpec& spec, const LocalFrame& frame,
                                   const Eigen::Vector2d& water) {
  spec.validate();  // before the cache is looked at
  const std::string key = cacheKey(spec, frame, water);
  const std::string path = chartCachePath(spec, frame, water);
  std::vector<Polygon> land;
  if (!path.empty() && readCache(path, key, land))
    return land;
  land = extract(spec, frame, water);
  if (!path.empty())
    writeCache(path, key, land);
  return land;
}

std::vector<Eigen::Vector2d> simplifyPolyline(const std::vector<Eigen::Vector2d>& line, double tolerance) {
  if (line.size() < 3 || !(tolerance > 0.0))
    return line;
  OGRLineString ls;
  for (const auto& p : line)
    ls.addPoint(p.x(), p.y());
  std::unique_ptr<OGRGeometry> thin(ls.Simplify(tolerance));
  const auto* out = thin ? dynamic_cast<const OGRLineString*>(thin.get()) : nullptr;
  if (!out || out->getNumPoints() < 2)
    return {line.front(), line.back()};
  std::vector<Eigen::Vector2d> kept;
  kept.reserve(static_cast<std::size_t>(out->getNumPoints()));
  for (int i = 0; i < out->getNumPoints(); ++i)
    kept.emplace_back(out->getX(i), out->getY(i));
  return kept;
}

}  // namespace asv
