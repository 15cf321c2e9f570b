// The plugins are thin adapters: each wraps one asv_core PlannerAlgorithm.
#pragma once

#include <memory>
#include <stdexcept>

#include "asv_planning/planner_plugin.h"

namespace asv_planning {

class AlgorithmPlugin : public PlannerPlugin {
public:
  void initialize(const std::string& name, const asv::ParamMap& config) override;
  asv::Plan makePlan(const asv::PlanningProblem& problem) override;
  std::string name() const override { return name_; }
  asv::ParamMap parameters() const override { return parameters_; }
  std::vector<asv::TargetDomain> domains(const asv::PlanningProblem& problem) const override {
    return algorithm_->domains(problem);
  }
  bool plansOnce() const override { return algorithm_->plansOnce(); }

protected:
  // `defaults`: the plugin's sea-scale defaults where the algorithm's own follow its paper's units;
  // keys given to initialize() override them. They apply in sea mode only (key `mode`, planning.h).
  explicit AlgorithmPlugin(std::unique_ptr<asv::PlannerAlgorithm> algorithm, asv::ParamMap defaults = {})
      : algorithm_(std::move(algorithm)), defaults_(std::move(defaults)) {}

private:
  std::unique_ptr<asv::PlannerAlgorithm> algorithm_;
  asv::ParamMap defaults_;
  asv::ParamMap parameters_;
  std::string name_;
  bool initialized_ = false;
};

class AcoPlugin : public AlgorithmPlugin {
public:
  AcoPlugin();
};
class DssaPlugin : public AlgorithmPlugin {
public:
  DssaPlugin();
};
class DssaPlusPlugin : public AlgorithmPlugin {
public:
  DssaPlusPlugin();
};
class MopsoPlugin : public AlgorithmPlugin {
public:
  MopsoPlugin();
};
class GaPlugin : public AlgorithmPlugin {
public:
  GaPlugin();
};

}  // namespace asv_planning
