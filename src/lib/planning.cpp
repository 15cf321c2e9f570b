#include "asv_core/planning.h"

namespace asv {

const char* toString(PlanStatus s) {
  switch (s) {
    case PlanStatus::Ok:
      return "ok";
    case PlanStatus::Fallback:
      return "fallback";
    case PlanStatus::NoSolution:
      break;
  }
  return "no_solution";
}

}  // namespace asv
