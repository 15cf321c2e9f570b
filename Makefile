# asv stack: the two commands are `make demo` and `make test`. See README.md.
SHELL := /bin/bash
.DEFAULT_GOAL := help

# Debian's ROS 1 needs Debian's python (a pyenv python3 lacks catkin_pkg): /usr/bin first.
export PATH := /usr/bin:/bin:$(PATH)
# Keep ROS logs inside the build tree and resolve this machine as localhost (no DNS needed).
export ROS_LOG_DIR := $(CURDIR)/build/ros_log
export ROS_HOSTNAME := localhost
JOBS ?= 2
# make test also runs the asv_core unit tests under ASan+UBSan (ASAN=0 skips them).
ASAN ?= 1
BUILD_TYPE ?= Release
# WERROR=1 (CI sets it): every compiler warning fails the build. Changing it rebuilds everything.
WERROR ?= 0
CXXFLAGS_EXTRA := $(if $(filter 1,$(WERROR)),-Werror,)
# ccache (scripts/setup installs it) caches every compilation outside the clone, so a fresh clone on the
# same machine (CI's) rebuilds from the cache. CCACHE_BASEDIR makes the clone's absolute paths relative,
# so two clones in different folders share the entries. CCACHE_DIR may point elsewhere.
export CCACHE_DIR ?= $(HOME)/.cache/ccache
export CCACHE_BASEDIR := $(CURDIR)
export CCACHE_MAXSIZE ?= 5G
LAUNCHER := $(if $(shell command -v ccache),-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache,)
CATKIN := catkin_make --source $(CURDIR) --build $(CURDIR)/build \
          -DPYTHON_EXECUTABLE=/usr/bin/python3 -DCMAKE_BUILD_TYPE=$(BUILD_TYPE) -DCATKIN_WHITELIST_PACKAGES="" \
          -DCMAKE_EXPORT_COMPILE_COMMANDS=ON -DCMAKE_CXX_FLAGS="$(CXXFLAGS_EXTRA)" $(LAUNCHER)
DEVEL := source $(CURDIR)/devel/setup.bash

.PHONY: help setup build build-nosetup test check install bench benchmark demo clean format lint eval eval-ros papers soak test-asan fuzz-long

help:
	@echo "asv stack: make targets"
	@echo "  make demo    install what is missing, build, run the headline scenario through ROS"
	@echo "  make test    install what is missing, build, run every unit test and rostest (time per phase)"
	@echo "  make check   build and run the unit tests alone (no master, no ASan): the inner loop"
	@echo "  make build   build the catkin workspace (build/, devel/)"
	@echo "  make install install every package into install/ (source install/setup.bash)"
	@echo "  make bench   run the Google Benchmark executables, JSON into out/bench/"
	@echo "  make eval    every scenario with every planner through asv_batch (out/eval/)"
	@echo "  make benchmark  generated situations, then real AIS traffic (tuning and test ranges) x every planner: out/benchmark/"
	@echo "  make eval-ros  the same pairs through the ROS pipeline in lockstep against asv_batch (out/eval_ros/)"
	@echo "  make papers  the four papers' experiments in paper mode against their numbers: docs/results/*.md,"
	@echo "               out/papers/summary.json (PAPERS_ARGS=\"--only dssa\" for one paper)"
	@echo "  make soak    2 simulated hours, 50 ships, the whole ROS pipeline: memory and rates (out/soak/)"
	@echo "  make test-asan  build and run the asv_core unit tests under ASan+UBSan (build_asan/)"
	@echo "  make fuzz-long  run each libFuzzer target for FUZZ_RUNS executions (10 M), out/fuzz/summary.txt"
	@echo "  make setup   install the Debian packages the stack needs (scripts/setup)"
	@echo "  make format  clang-format every C++ file"
	@echo "  make lint    clang-tidy (.clang-tidy: bug patterns, performance, functions <= 120 lines)"
	@echo "  make clean   remove build/, devel/ and out/"

setup:
	@scripts/setup

# catkin's test environment (build/catkin_generated/setup_cached.sh) keeps the PYTHONPATH of the first
# configure, which leaves out devel/lib/python3/dist-packages if it did not exist yet: then no python
# test node can import asv_msgs. So the folder exists before the first configure, and a build tree
# configured without it is configured again.
build: setup
	@$(MAKE) --no-print-directory build-nosetup

# The catkin build alone (make build and scripts/test_all.sh, which times setup on its own).
build-nosetup:
	@mkdir -p devel/lib/python3/dist-packages
	@$(CATKIN) -j$(JOBS)
	@grep -q "^export PYTHONPATH=.*$(CURDIR)/devel/lib/python3/dist-packages" build/catkin_generated/setup_cached.sh \
	  || $(CATKIN) -j$(JOBS) --force-cmake

# make test and make check (scripts/test_all.sh): each phase timed, test executables JOBS at a time,
# logs in build/test_logs/, the closing line `N passed, N failed, N skipped`.
export ASV_CATKIN := $(CATKIN)
export JOBS ASAN
test:
	@scripts/test_all.sh

check:
	@scripts/test_all.sh --check

# The install space (install/): every package's nodes, launch files, configs, scenarios and headers.
# make test checks it on its own (scripts/install_check.py). Then: source install/setup.bash.
install: build
	@mkdir -p install && touch install/CATKIN_IGNORE  # install/ lies in the source space: catkin must not find its packages twice
	@$(CATKIN) -j$(JOBS) install

bench: build
	@mkdir -p out/bench
	@for b in devel/lib/asv_core/bench/*; do \
	  name=$$(basename $$b); echo "== $$name ($$(nproc) cores)"; \
	  $$b --benchmark_out=out/bench/$$name.json --benchmark_out_format=json || exit 1; \
	done
	@scripts/ais_cli_throughput.py
	@echo "bench: JSON results in out/bench/"

# The headline scenario (Hu et al. Fig. 6: a give-way target that stands on, the own ship's MOPSO
# planner) end to end through ROS with rviz recorded off-screen; DEMO_SCENARIO / DEMO_PLANNER / DEMO_RATE
# choose another run.
DEMO_SCENARIO ?= hu_non_compliant
DEMO_PLANNER ?= mopso
DEMO_RATE ?= 30
demo: build
	@echo "demo: $(DEMO_SCENARIO) with $(DEMO_PLANNER) through the ROS pipeline at $(DEMO_RATE)x real time (rviz recorded off-screen)..."
	@rviz/record.sh $(DEMO_SCENARIO) $(DEMO_PLANNER) $(DEMO_RATE) || { echo "demo: FAILED (see out/$(DEMO_SCENARIO)/$(DEMO_PLANNER)/launch.log)"; exit 1; }
	@test -s out/$(DEMO_SCENARIO)/$(DEMO_PLANNER)/result.json || { echo "demo: FAILED (no result; see out/$(DEMO_SCENARIO)/$(DEMO_PLANNER)/launch.log)"; exit 1; }
	@grep "evaluator_node: " out/$(DEMO_SCENARIO)/$(DEMO_PLANNER)/launch.log | grep -v -e "own ship '" -e "written to" \
	  | sed -e 's/.*evaluator_node: //' -e 's/\x1b\[[0-9;]*m//g' || true
	@echo "demo: result out/$(DEMO_SCENARIO)/$(DEMO_PLANNER)/result.json, bag out/$(DEMO_SCENARIO)/$(DEMO_PLANNER)/run.bag,"
	@echo "      video out/$(DEMO_SCENARIO)/$(DEMO_PLANNER).mp4, final frame out/$(DEMO_SCENARIO)/$(DEMO_PLANNER).png"

clean:
	rm -rf build build_asan devel install out CMakeLists.txt

# make test fails on any difference (scripts/format_check.py).
format:
	@find src asv_* -name '*.cpp' -o -name '*.h' | xargs clang-format -i

# clang-tidy with .clang-tidy over every C++ source of the stack that the build compiles
# (build/compile_commands.json); fails on any finding. About 4 minutes on 2 cores.
lint: build
	@scripts/lint.sh $(JOBS)

# Batch evaluation (scripts/eval.sh, docs/evaluation.md): every scenario with every planner that applies,
# SEEDS seeds each, through asv_batch; out/eval/results.jsonl, report.md and plots/.
SEEDS ?= 3
eval: build
	@$(DEVEL) && scripts/eval.sh $(SEEDS)

# Monte-Carlo benchmark (scripts/benchmark.py, docs/evaluation.md): asv_scenario_gen situations of a tuning
# and a test seed range x every planner through asv_batch under GNU parallel; out/benchmark/report.md,
# summary.json and plots. BENCHMARK_ARGS="--situations 90 --planners ga" narrows it. Then real traffic
# (scripts/real_traffic.py): the own ship in the place of logged vessels of $ASV_AIS_LOG (default the
# shared New York hour; skipped, and said so, without it), tuning and test ranges by time, against the
# masters: out/benchmark/real/report.md. REAL_TRAFFIC_ARGS="--per-start 1 --planners aco" narrows it.
BENCHMARK_ARGS ?=
REAL_TRAFFIC_ARGS ?=
benchmark: build
	@$(DEVEL) && scripts/benchmark.py $(BENCHMARK_ARGS) && scripts/real_traffic.py $(REAL_TRAFFIC_ARGS)

# Batch and ROS agree (scripts/eval_ros.py): every scenario/planner pair once through scenario.launch
# lockstep:=true and once through asv_batch; out/eval_ros/report.md, exit 1 on a disagreement.
# EVAL_ROS_ARGS="--scenarios head_on --planners ga" narrows it.
EVAL_ROS_ARGS ?=
eval-ros: build
	@$(DEVEL) && scripts/eval_ros.py $(EVAL_ROS_ARGS)

# The experiments of the four papers, closed loop through asv_batch, each planner in paper mode, every
# reported number compared two-sided: docs/results/{aco,dssa,mopso,ga}.md and out/papers/summary.json.
papers: build
	@$(DEVEL) && scripts/papers.py $(PAPERS_ARGS)

# Soak (docs/reliability.md): SOAK_SIM_TIME simulated seconds of asv_bringup/test/soak_50_ships.yaml through
# the whole pipeline as fast as it sustains; out/soak/summary.json, exit 1 on a failed criterion.
SOAK_SIM_TIME ?= 7200
soak: build
	@$(DEVEL) && scripts/soak.py --sim-time $(SOAK_SIM_TIME)

# Reliability (docs/reliability.md): the asv_core unit tests under AddressSanitizer, LeakSanitizer and
# UndefinedBehaviorSanitizer in build_asan/, JUnit XML in build/test_results/asan/.
test-asan: setup
	@scripts/asan_tests.sh; status=$$?; scripts/test_summary.py build/test_results/asan && exit $$status

# Long fuzzing: every libFuzzer target of scripts/fuzz_smoke.sh for FUZZ_RUNS executions, niced; logs,
# grown corpora and any crash input in out/fuzz/, one line per target in out/fuzz/summary.txt.
FUZZ_RUNS ?= 10000000
fuzz-long: setup
	@nice -n 15 scripts/fuzz_long.sh $(FUZZ_RUNS)
