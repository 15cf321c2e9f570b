// The main of an asv_core command-line tool: a usage error prints the usage and exits 2; an exception
// while running prints "<tool>: <reason>" and exits 1; otherwise the tool's own exit status.
#pragma once

#include <exception>
#include <iostream>

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
