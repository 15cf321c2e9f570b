# asv stack: the two commands are `make demo` and `make test`. See README.md.
SHELL := /bin/bash
.DEFAULT_GOAL := help

# Debian's ROS 1 needs Debian's python (a pyenv python3 lacks catkin_pkg): /usr/bin first.
export PATH := /usr/bin:/bin:$(PATH)
# Keep ROS logs inside the build tree and resolve this machine as localhost (no DNS needed).
export ROS_LOG_DIR := $(CURDIR)/build/ros_log
export ROS_HOSTNAME := localhost
JOBS ?= 2
BUILD_TYPE ?= Release
CATKIN := catkin_make --source $(CURDIR) --build $(CURDIR)/build \
          -DPYTHON_EXECUTABLE=/usr/bin/python3 -DCMAKE_BUILD_TYPE=$(BUILD_TYPE) -DCATKIN_WHITELIST_PACKAGES=""
DEVEL := source $(CURDIR)/devel/setup.bash

.PHONY: help setup build test bench demo clean format

help:
	@echo "asv stack: make targets"
	@echo "  make demo    install what is missing, build, run the headline scenario through ROS"
	@echo "  make test    install what is missing, build, run every unit test and rostest"
	@echo "  make build   build the catkin workspace (build/, devel/)"
	@echo "  make bench   run the Google Benchmark executables, JSON into out/bench/"
	@echo "  make setup   install the Debian packages the stack needs (scripts/setup)"
	@echo "  make format  clang-format every C++ file"
	@echo "  make clean   remove build/, devel/ and out/"

setup:
	@scripts/setup

build: setup
	@$(CATKIN) -j$(JOBS)

test: build
	@$(CATKIN) -j$(JOBS) tests
	@rm -rf build/test_results
	@$(DEVEL) && $(CATKIN) run_tests -j1 > build/run_tests.log 2>&1 || true
	@grep -E "^\[ROSTEST\].*results summary|FAILED|Segmentation|Aborted|MISSING" build/run_tests.log || true
	@scripts/fuzz_smoke.sh 20 || true
	@scripts/test_summary.py build/test_results

bench: build
	@mkdir -p out/bench
	@for b in devel/lib/asv_core/bench/*; do \
	  name=$$(basename $$b); echo "== $$name ($$(nproc) cores)"; \
	  $$b --benchmark_out=out/bench/$$name.json --benchmark_out_format=json || exit 1; \
	done
	@echo "bench: JSON results in out/bench/"

demo: build
	@mkdir -p out/demo && rm -f out/demo/risk_table.txt
	@$(DEVEL) && roslaunch asv_risk demo.launch 2>&1 | tee out/demo/demo.log | grep -v -E "^\s*$$|process\[|started roslaunch|ROS_MASTER_URI|setting /run_id|auto-starting new master|core service|SUMMARY|PARAMETERS|NODES|^ \* |^  /|^\s+\w+ \(" || true
	@test -s out/demo/risk_table.txt || { echo "demo: FAILED (no risk table; see out/demo/demo.log)"; exit 1; }
	@echo "demo: log in out/demo/demo.log, risk table in out/demo/risk_table.txt"

clean:
	rm -rf build devel install out CMakeLists.txt

format:
	@find src asv_* -name '*.cpp' -o -name '*.h' | xargs clang-format -i
