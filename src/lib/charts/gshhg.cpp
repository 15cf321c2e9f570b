// GSHHG land through GMT. GMT keeps GSHHG in binned files and dumps the shorelines of a region as
// open pieces cut at bin and region edges (`gmt coast -M -W`), not as polygons. Land polygons are made
// from them exactly: the pieces and the region's outline are noded and polygonised (GEOS, through OGR)
// into the faces of the map, and `gmt gmtselect` tells which faces are land (GSHHG levels 1 and 3:
// land, islands in lakes) and which water (ocean, lakes, ponds).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "asv_core/charts/charts.h"
#include "ogr_land.h"

namespace asv::charts_detail {
namespace {

// A private folder for one extraction: GMT writes its gmt.history into $GMT_TMPDIR (else into the
// working folder of whatever program loads a chart), and the points for gmtselect go there too.
struct WorkDir {
  std::string path;
  WorkDir() {
    char tmpl[] = "/tmp/asv-gshhg-XXXXXX";
    if (!mkdtemp(tmpl))
      throw ChartError("GSHHG: cannot create a temporary folder");
    path = tmpl;
  }
  ~WorkDir() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
  WorkDir(const WorkDir&) = delete;
  WorkDir& operator=(const WorkDir&) = delete;
  std::string gmt() const { return "GMT_TMPDIR=" + path + " gmt "; }
};

// Runs a shell command; returns its standard output and error. Throws ChartError when it fails.
std::string run(const std::string& cmd) {
  FILE* pipe = popen((cmd + " 2>&1").c_str(), "r");
  if (!pipe)
    throw ChartError("GSHHG: cannot start `" + cmd + "`");
  std::string out;
  std::array<char, 4096> buf{};
  size_t n = 0;
  while ((n = fread(buf.data(), 1, buf.size(), pipe)) > 0)
    out.append(buf.data(), n);
  const int status = pclose(pipe);
  if (WIFEXITED(status) && WEXITSTATUS(status) == 127)
    throw ChartError(
        "GSHHG charts need GMT and its GSHHG data (Debian packages gmt, gmt-gshhg-high; "
        "scripts/setup installs them): `gmt` was not found");
  if (status != 0)
    throw ChartError("GSHHG: `" + cmd + "` failed: " + out);
  return out;
}

std::string region(const LonLatBox& b) {
  char s[160];
  std::snprintf(s, sizeof s, "-R%.7f/%.7f/%.7f/%.7f", b.west, b.east, b.south, b.north);
  return s;
}

// Snaps to 1e-7 deg (1 cm) so that the ends of pieces cut at the same bin edge coincide exactly.
double snap(double deg) {
  return std::round(deg * 1e7) / 1e7;
}

// The shoreline pieces of the region as line strings, plus the region's outline.
GeomPtr shorelinePieces(const WorkDir& work, char code, const LonLatBox& box) {
  std::istringstream in(run(work.gmt() + "coast " + region(box) + " -D" + code + " -M -W -Vq"));
  auto lines = std::make_unique<OGRMultiLineString>();
  OGRLineString piece;
  auto flush = [&] {
    if (piece.getNumPoints() >= 2)
      lines->addGeometry(&piece);
    piece.empty();
  };
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#')
      continue;
    if (line[0] == '>') {
      flush();
      continue;
    }
    double lon = 0.0, lat = 0.0;
    if (std::sscanf(line.c_str(), "%lf %lf", &lon, &lat) != 2)
      throw ChartError("GSHHG: unexpected line from gmt coast: " + line);
    lon = snap(lon), lat = snap(lat);
    const int k = piece.getNumPoints();
    if (k == 0 || piece.getX(k - 1) != lon || piece.getY(k - 1) != lat)
      piece.addPoint(lon, lat);
  }
  flush();
  OGRLineString outline;
  for (const auto& [lon, lat] : {std::pair{box.west, box.south},
                                 {box.east, box.south},
                                 {box.east, box.north},
                                 {box.west, box.north},
                                 {box.west, box.south}})
    outline.addPoint(lon, lat);
  lines->addGeometry(&outline);
  return GeomPtr(lines.release());
}

// Indices of the faces whose inside point GSHHG calls land (gmt gmtselect keeps land and islands in lakes).
std::vector<bool> landFaces(const WorkDir& work, char code, const LonLatBox& box,
                            const std::vector<OGRPoint>& inside) {
  const std::string path = work.path + "/points.txt";
  {
    std::ofstream f(path);
    f.precision(12);
    for (size_t i = 0; i < inside.size(); ++i)
      f << inside[i].getX() << ' ' << inside[i].getY() << ' ' << i << '\n';
  }
  const std::string out =
      run(work.gmt() + "gmtselect " + region(box) + " -D" + code + " -Ns/k/s/k/s -Vq " + path);
  std::vector<bool> land(inside.size(), false);
  std::istringstream in(out);
  double lon = 0.0, lat = 0.0, idx = 0.0;
  while (in >> lon >> lat >> idx)
    if (idx >= 0 && idx < static_cast<double>(land.size()))
      land[static_cast<size_t>(idx)] = true;
  return land;
}

}  // namespace

std::vector<GeomPtr> readGshhgLand(char code, const LonLatBox& box) {
  const WorkDir work;
  const GeomPtr pieces = shorelinePieces(work, code, box);
  const OGRLineString* first = pieces->toMultiLineString()->getGeometryRef(0);
  OGRPoint seed;
  first->StartPoint(&seed);
  const GeomPtr noded(pieces->Union(&seed));  // GEOS nodes line work when it unions it
  const GeomPtr faces(noded ? noded->Polygonize() : nullptr);
  if (!faces)
    throw ChartError("GSHHG: the shorelines of " + region(box) + " could not be polygonised");
  std::vector<OGRPoint> inside;
  std::vector<const OGRPolygon*> polys;
  for (const OGRGeometry* g : *faces->toGeometryCollection()) {
    OGRPoint p(0.0, 0.0);  // OGR fills only a point that is not empty
    if (wkbFlatten(g->getGeometryType()) == wkbPolygon && g->toPolygon()->PointOnSurface(&p) == OGRERR_NONE) {
      inside.push_back(p);
      polys.push_back(g->toPolygon());
    }
  }
  const std::vector<bool> land = landFaces(work, code, box, inside);
  OGRMultiPolygon all;
  for (size_t i = 0; i < polys.size(); ++i)
    if (land[i])
      all.addGeometry(polys[i]);
  std::vector<GeomPtr> result;
  if (all.IsEmpty())
    return result;
  const GeomPtr merged(all.UnionCascaded());  // adjacent land faces become one polygon
  if (!merged)
    throw ChartError("GSHHG: merging the land faces failed");
  result.push_back(GeomPtr(merged->clone()));
  return result;
}

}  // namespace asv::charts_detail
