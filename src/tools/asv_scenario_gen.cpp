// asv_scenario_gen: format-1 scenario files of the standard encounters, drawn from a seed, with targets
// that break the rules, converging traffic and coasts (asv_core/sim/scenario_gen.h; docs/evaluation.md).
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <string>

#include "asv_core/sim/scenario_gen.h"
#include "tool_main.h"

namespace {

using namespace asv;

const char* const kUsage =
    "usage: asv_scenario_gen --out DIR [--class NAME|all] [--count N] [--seed S] [--first I]\n"
    "                        [--own-speed MIN,MAX] [--max-targets N] [--rule-breakers P] [--quiet]\n"
    "                        [--list-classes] [-h|--help]\n"
    "\n"
    "Writes N scenario files (format 1) to DIR, situation I..I+N-1 of seed S: the same arguments give the\n"
    "same files, byte for byte. Each target is placed to reach its closest point of approach after 8-30\n"
    "min at 0-0.3 nm (the families that probe the referee: as --list-classes says); a draw whose targets "
    "start inside twice the minimum separation, whose encounter\n"
    "classifies otherwise, whose targets collide or ground on their own, or where no course or speed\n"
    "change of the own ship at the moment a rule-breaker's breach shows could keep 0.5 nm, is drawn again\n"
    "(counted). Also writes DIR/manifest.tsv: file, class, targets, rule-breakers, redraws.\n"
    "\n"
    "  --out DIR            output folder (created)\n"
    "  --class NAME|all     one family (see --list-classes) or all (default): situation I is then\n"
    "                       class I mod 15, in --list-classes order\n"
    "  --count N            number of files (default 9)\n"
    "  --seed S             seed (default 1)\n"
    "  --first I            index of the first situation (default 0)\n"
    "  --own-speed MIN,MAX  own-ship speed range [kn] (default 8,16; a 3-DOF own ship runs at 12)\n"
    "  --max-targets N      most targets of multi and converging situations (default 5)\n"
    "  --rule-breakers P    share of give-way targets that break the rules in multi and converging (0.2)\n"
    "  --quiet              no progress line\n"
    "  --list-classes       print the classes and exit\n"
    "  -h, --help           this help\n"
    "\n"
    "Exit status: 0, 1 when a file cannot be written or a class finds no acceptable draw, 2 on a usage\n"
    "error.\n";

const char* const kClassHelp =
    "head_on            one ship met end on; both give way (Rule 14)\n"
    "crossing_give_way  one ship crossing from starboard; the own ship gives way (Rules 15, 16)\n"
    "crossing_stand_on  one ship crossing from port gives way; the own ship stands on (Rule 17)\n"
    "overtaking         the own ship overtakes a slower ship (Rule 13)\n"
    "being_overtaken    a faster ship overtakes the own ship and keeps out of the way (Rules 13, 17)\n"
    "rule_breaker       one ship that should give way stands on or turns to port (Rules 2, 17)\n"
    "multi              2-5 ships of any encounter, CPAs at independent times, 20 % rule-breakers\n"
    "converging         2-5 ships whose CPAs fall within 3 minutes of each other, 20 % rule-breakers\n"
    "coastal            1-3 ships with a coast on one side of the route or a channel\n"
    "offset_head_on     one ship met nearly head-on 0.3-0.8 nm off either side; she gives way, never acts,\n"
    "                   or acts late and little\n"
    "head_on_starboard_occupied\n"
    "                   head-on, with a ship at anchor, a slow ship or a coast on the starboard side; a\n"
    "                   starboard manoeuvre is still open (Rules 14, 8)\n"
    "head_on_crossing_boundary\n"
    "                   one ship 8-35 deg off the reciprocal on either bow: either side of the head-on /\n"
    "                   crossing boundary (Rules 14, 15)\n"
    "stand_on_remote_duty\n"
    "                   a ship crossing from port gives way (the own ship stands on), and a slow ship ahead\n"
    "                   that she overtakes 0.5-0.9 nm abeam after 20-30 min (Rule 17 with several ships)\n"
    "late_give_way      one ship that should give way (head-on, from port, overtaking) acts only 6 min\n"
    "                   before the CPA and by 15 deg (Rules 16, 17(a)(ii), 17(b))\n"
    "route_bend_crossing\n"
    "                   the own route bends 30-60 deg either way after 5-15 min; a ship crossing the new\n"
    "                   leg from either side meets her 5-15 min later, and not the first leg (Rules 15,\n"
    "                   17, 8)\n";

struct Args {
  std::string out, cls = "all";
  long long count = 9, first = 0;
  unsigned long long seed = 1;
  bool quiet = false;
  GeneratorConfig cfg;
};

bool option(Args& a, const std::string& k, const std::string& v) {
  double x = 0.0;
  if (k == "--out")
    a.out = v;
  else if (k == "--class")
    a.cls = v;
  else if (k == "--count" && toolNumber(v, x) && x >= 1 && x == double(static_cast<long long>(x)))
    a.count = static_cast<long long>(x);
  else if (k == "--seed" && toolNumber(v, x) && x >= 0 && x == double(static_cast<long long>(x)))
    a.seed = static_cast<unsigned long long>(x);
  else if (k == "--first" && toolNumber(v, x) && x >= 0 && x == double(static_cast<long long>(x)))
    a.first = static_cast<long long>(x);
  else if (k == "--max-targets" && toolNumber(v, x) && x >= 2 && x == double(int(x)))
    a.cfg.max_targets = int(x);
  else if (k == "--rule-breakers" && toolNumber(v, x))
    a.cfg.rule_breaker_share = x;
  else if (k == "--own-speed" && v.find(',') != std::string::npos && toolNumber(v.substr(0, v.find(',')), x))
    a.cfg.own_speed_min_kn = x, a.cfg.own_speed_max_kn = std::strtod(v.c_str() + v.find(',') + 1, nullptr);
  else
    return false;
  return true;
}

bool parse(int argc, char** argv, Args& a) {
  for (int i = 1; i < argc; ++i) {
    const std::string k = argv[i];
    exitOnHelp(k, kUsage);
    if (k == "--list-classes") {
      std::cout << kClassHelp;
      std::exit(0);
    }
    if (k == "--quiet") {
      a.quiet = true;
      continue;
    }
    if (i + 1 >= argc || !option(a, k, argv[i + 1])) {
      std::cerr << "asv_scenario_gen: bad or incomplete option " << k << "\n";
      return false;
    }
    ++i;
  }
  if (a.out.empty()) {
    std::cerr << "asv_scenario_gen: --out is required\n";
    return false;
  }
  if (a.cls != "all" && !situationClassFromString(a.cls)) {
    std::cerr << "asv_scenario_gen: unknown class '" << a.cls << "' (asv_scenario_gen --list-classes)\n";
    return false;
  }
  try {
    a.cfg.validate();
  } catch (const std::invalid_argument& e) {
    std::cerr << "asv_scenario_gen: " << e.what() << "\n";
    return false;
  }
  return true;
}

SituationClass classOf(const Args& a, unsigned long long index) {
  if (a.cls != "all")
    return *situationClassFromString(a.cls);
  const auto& all = allSituationClasses();
  return all[index % all.size()];
}

int breakers(const Scenario& s) {
  int n = 0;
  for (const auto& t : s.targets)
    n += t.behaviour == Behaviour::NonCompliant || t.behaviour == Behaviour::PortTurn ||
         t.behaviour == Behaviour::LateGiveWay;
  return n;
}

int run(const Args& a) {
  std::filesystem::create_directories(a.out);
  std::ofstream manifest(a.out + "/manifest.tsv");
  manifest << "file\tclass\ttargets\trule_breakers\tredraws\n";
  std::map<std::string, int> refused;
  const bool progress = !a.quiet && isatty(STDERR_FILENO);
  for (long long i = 0; i < a.count; ++i) {
    const unsigned long long index = static_cast<unsigned long long>(a.first + i);
    const GeneratedScenario g = generateScenario(a.cfg, classOf(a, index), a.seed, index);
    const std::string file = g.scenario.name + ".yaml";
    std::ofstream out(a.out + "/" + file);
    out << g.yaml;
    int redraws = 0;
    for (const auto& [reason, n] : g.refused)
      refused[reason] += n, redraws += n;
    manifest << file << "\t" << toString(g.situation) << "\t" << g.scenario.targets.size() << "\t"
             << breakers(g.scenario) << "\t" << redraws << "\n";
    if (!out || !manifest) {
      std::cerr << "asv_scenario_gen: cannot write " << a.out << "/" << file << "\n";
      return 1;
    }
    if (progress)
      std::cerr << "\rasv_scenario_gen: " << i + 1 << "/" << a.count << " " << file << "        "
                << std::flush;
  }
  if (progress)
    std::cerr << "\n";
  if (!a.quiet) {
    std::cerr << "asv_scenario_gen: " << a.count << " scenario(s) in " << a.out << "/\n";
    for (const auto& [reason, n] : refused)
      std::cerr << "  redrawn " << n << " time(s): " << reason << "\n";
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return toolMain<Args>("asv_scenario_gen", kUsage, argc, argv, parse, run);
}
