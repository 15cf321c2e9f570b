// The main of an asv_core command-line tool: a usage error prints the usage and exits 2; an exception
// while running prints "<tool>: <reason>" and exits 1; otherwise the tool's own exit status.
#pragma once

#include <cmath>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>

// A whole argument as a finite number (no trailing text).
inline bool toolNumber(const std::string& v, double& out) {
  char* end = nullptr;
  out = std::strtod(v.c_str(), &end);
  return !v.empty() && end && *end == '\0' && std::isfinite(out);
}

// -h or --help: prints the usage on stdout and exits 0.
inline void exitOnHelp(const std::string& arg, const char* usage) {
  if (arg == "-h" || arg == "--help") {
    std::cout << usage;
    std::exit(0);
  }
}

template <typename Args, typename Parse, typename Run>
int toolMain(const char* name, const char* usage, int argc, char** argv, Parse parse, Run run) {
  Args a;
  if (!parse(argc, argv, a)) {
    std::cerr << usage;
    return 2;
  }
  try {
    return run(a);
  } catch (const std::exception& e) {
    std::cerr << name << ": " << e.what() << '\n';
    return 1;
  }
}
