// asv_dssa_experiments: the three experiments of Hirayama et al. (2019), Sec. 5 (Tables 1-3), for DSSA
// and the three DSSA+ variants, printed as a markdown table beside the paper's figures.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "asv_core/papers/dssa_experiments.h"

namespace {

using namespace asv;

const char* const kUsage =
    "usage: asv_dssa_experiments [--trials N] [--seed S] [--variant NAME|all] [--scenario NAME|all]\n"
    "                            [--markdown OUT] [-h|--help]\n"
    "\n"
    "Runs the experiments of Hirayama et al. (2019), Sec. 5: two ships pushing each other (Table 1),\n"
    "16 ships crossing (Table 2), three ships overtaking (Table 3), in the paper's units (800 x 800,\n"
    "speed 25, TimeWindow 20, detection range 500, p = 0.8), and prints a markdown table of total path\n"
    "length, travel time, detour rate and success rate beside the paper's figures.\n"
    "\n"
    "  --trials N        trials per scenario and variant (default: the paper's, 20 / 50 / 20)\n"
    "  --seed S          seed of the first trial; trial k uses S + k (default 1)\n"
    "  --variant NAME    dssa | dssa_plus_sc | dssa_plus_cs | dssa_plus_eq | all (default all)\n"
    "  --scenario NAME   two_ships | sixteen_ships | three_ships | all (default all)\n"
    "  --markdown OUT    also write the table to OUT\n"
    "  -h, --help        this help\n"
    "\n"
    "Exit status: 0, 1 when OUT cannot be written, 2 on a usage error.\n";

std::string fmt(double v, int prec) {
  if (!std::isfinite(v))
    return "-";
  char b[64];
  std::snprintf(b, sizeof b, "%.*f", prec, v);
  return b;
}

bool parseInt(const char* s, long long& out) {
  char* e = nullptr;
  out = std::strtoll(s, &e, 10);
  return e != s && *e == '\0';
}

struct Args {
  long long trials = -1, seed = 1;
  std::string variant = "all", scenario_name = "all", markdown;
};

// The command line into `args`: -1 to go on, else the exit status (0 after --help, 2 on a usage error).
int parseArgs(int argc, char** argv, Args& args) {
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&](const char* name) -> const char* {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "asv_dssa_experiments: %s needs a value\n%s", name, kUsage);
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "-h" || a == "--help") {
      std::fputs(kUsage, stdout);
      return 0;
    } else if (a == "--trials") {
      if (!parseInt(value("--trials"), args.trials) || args.trials < 1) {
        std::fprintf(stderr, "asv_dssa_experiments: --trials needs a positive integer\n");
        return 2;
      }
    } else if (a == "--seed") {
      if (!parseInt(value("--seed"), args.seed)) {
        std::fprintf(stderr, "asv_dssa_experiments: --seed needs an integer\n");
        return 2;
      }
    } else if (a == "--variant") {
      args.variant = value("--variant");
    } else if (a == "--scenario") {
      args.scenario_name = value("--scenario");
    } else if (a == "--markdown") {
      args.markdown = value("--markdown");
    } else {
      std::fprintf(stderr, "asv_dssa_experiments: unknown argument '%s'\n%s", a.c_str(), kUsage);
      return 2;
    }
  }
  return -1;
}

// One paper table: our figures beside the paper's for each variant.
std::string table(const DssaScenario& sc, const std::vector<std::string>& variants, int n, long long seed) {
  const char* title = sc.name == "two_ships"       ? "Table 1: two ships pushing each other"
                      : sc.name == "sixteen_ships" ? "Table 2: 16 ships crossing each other"
                                                   : "Table 3: three ships overtaking or being overtaken";
  std::vector<DssaExperimentSummary> sum;
  sum.reserve(variants.size());
  for (const auto& v : variants)
    sum.push_back(runDssaExperiment(sc, v, n, static_cast<uint64_t>(seed)));
  std::ostringstream out;
  out << "### " << title << " (" << n << " trials, seeds " << seed << ".." << seed + n - 1 << ")\n\n";
  out << "| |";
  for (const auto& v : variants)
    out << " " << dssaVariantLabel(v) << " | (paper) |";
  out << "\n|---|";
  for (std::size_t i = 0; i < variants.size(); ++i)
    out << "---:|---:|";
  out << "\n";
  auto row = [&](const char* label, auto ours, auto paper) {
    out << "| " << label << " |";
    for (std::size_t i = 0; i < variants.size(); ++i) {
      const DssaPaperFigures pf = dssaPaperFigures(sc.name, variants[i]);
      out << " " << ours(sum[i]) << " | " << paper(pf) << " |";
    }
    out << "\n";
  };
  const auto none = [](const DssaPaperFigures&) { return std::string(""); };
  row(
      "Total length of paths", [](const DssaExperimentSummary& s) { return fmt(s.total_path_length, 1); },
      [](const DssaPaperFigures& p) { return fmt(p.successes >= 0 ? p.total_path_length : NAN, 1); });
  row(
      "Travel time of each ship", [](const DssaExperimentSummary& s) { return fmt(s.travel_time, 1); },
      [](const DssaPaperFigures& p) { return fmt(p.successes >= 0 ? p.travel_time : NAN, 1); });
  row(
      "Detour rate of each ship", [](const DssaExperimentSummary& s) { return fmt(s.detour_rate, 2); },
      [](const DssaPaperFigures& p) { return fmt(p.successes >= 0 ? p.detour_rate : NAN, 2); });
  row(
      "Success rate",
      [](const DssaExperimentSummary& s) {
        return std::to_string(s.successes) + "/" + std::to_string(s.trials);
      },
      [](const DssaPaperFigures& p) {
        return p.successes >= 0 ? std::to_string(p.successes) + "/" + std::to_string(p.trials)
                                : std::string("-");
      });
  row(
      "Collisions", [](const DssaExperimentSummary& s) { return std::to_string(s.collisions); }, none);
  row(
      "Min separation", [](const DssaExperimentSummary& s) { return fmt(s.min_separation, 1); }, none);
  row(
      "Rounds per search phase (mean)", [](const DssaExperimentSummary& s) { return fmt(s.mean_rounds, 1); },
      none);
  row(
      "Search phases at the round limit",
      [](const DssaExperimentSummary& s) { return std::to_string(s.non_quiescent_phases); }, none);
  out << "\n";
  return out.str();
}

}  // namespace

int main(int argc, char** argv) {
  Args args;
  if (const int status = parseArgs(argc, argv, args); status >= 0)
    return status;
  std::vector<std::string> variants;
  if (args.variant == "all") {
    variants = dssaPaperVariants();
  } else {
    try {
      DssaConfig::preset(args.variant);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "asv_dssa_experiments: %s\n", e.what());
      return 2;
    }
    variants = {args.variant};
  }
  std::vector<DssaScenario> scenarios;
  for (auto& s : dssaPaperScenarios())
    if (args.scenario_name == "all" || args.scenario_name == s.name)
      scenarios.push_back(s);
  if (scenarios.empty()) {
    std::fprintf(stderr, "asv_dssa_experiments: unknown scenario '%s'\n", args.scenario_name.c_str());
    return 2;
  }
  std::string all;
  for (const auto& sc : scenarios) {
    const std::string t =
        table(sc, variants, args.trials > 0 ? static_cast<int>(args.trials) : sc.trials, args.seed);
    std::cout << t << std::flush;
    all += t;
  }
  if (!args.markdown.empty()) {
    std::ofstream f(args.markdown);
    f << all;
    if (!f) {
      std::fprintf(stderr, "asv_dssa_experiments: cannot write '%s'\n", args.markdown.c_str());
      return 1;
    }
  }
  return 0;
}
