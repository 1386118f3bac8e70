# Thin wrapper: everything real lives in CMake (build, tests) and verification/ (figures).
BUILD_DIR ?= build
JOBS      ?= $(shell nproc)

.PHONY: deps configure build test figures studies bench docs clean sanitize mutants lab

deps:
	@bash .ci/install-deps.sh

configure: deps
	@mkdir -p $(BUILD_DIR)
	@cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release > $(BUILD_DIR)/configure.log 2>&1 || (cat $(BUILD_DIR)/configure.log; exit 1)

build: configure
	@cmake --build $(BUILD_DIR) -j $(JOBS)

# Builds what the tests run (CMake target test_programs: the tests, the CLI, docs_trace), not the
# drivers of make figures, which make build compiles (.ci/run does, after make test).
test: configure
	@cmake --build $(BUILD_DIR) --target test_programs -j $(JOBS)
	@cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)

# The lab build (README, "Editing a kernel"; paper/13_lab.md): the command-line program alone at -O1 (MPM_LAB_FLAGS),
# on the reference kernels alone (CMake build type Lab), in its own folder: after an edit of a kernel, make lab again
# rebuilds the two run units (and the one-line version unit when the tree's version changes).
LAB_DIR ?= build-lab
lab: deps
	@mkdir -p $(LAB_DIR)
	@cmake -S . -B $(LAB_DIR) -DCMAKE_BUILD_TYPE=Lab > $(LAB_DIR)/configure.log 2>&1 || (cat $(LAB_DIR)/configure.log; exit 1)
	@cmake --build $(LAB_DIR) --target mpm_cli -j $(JOBS)

# AddressSanitizer + UndefinedBehaviorSanitizer: only the programs the tests run (the
# test program, the CLI, docs_trace), at -O1 with assertions on, in their own folder; then the tests,
# the fuzzer and every scene x shape x integrator for a few steps (tests/sanitize_scenes.sh, a ctest
# of that folder); the docs check in Chromium (docs_browser) is left to make test.
SANITIZE_DIR ?= build-sanitize
SANITIZE_FLAGS = -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
sanitize: deps
	@mkdir -p $(SANITIZE_DIR)
	@cmake -S . -B $(SANITIZE_DIR) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" \
	  -DCMAKE_CXX_FLAGS="$(SANITIZE_FLAGS)" -DCMAKE_EXE_LINKER_FLAGS="$(SANITIZE_FLAGS)" \
	  > $(SANITIZE_DIR)/configure.log 2>&1 || (cat $(SANITIZE_DIR)/configure.log; exit 1)
	@cmake --build $(SANITIZE_DIR) --target test_programs -j $(JOBS)
	@cd $(SANITIZE_DIR) && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 ctest --output-on-failure -j $(JOBS) -E '^docs_browser$$'

# The paper's figures (Figs. 4, 6-13) with their claims (verification/make_figures.sh), into results/ and the
# report's first part; builds only what they run (CMake target figure_programs), timed with the runs
# (results/figures_budget.csv).
figures: configure
	@bash verification/make_figures.sh $(BUILD_DIR) $(JOBS)

# Everything beyond the paper's figures (verification/make_studies.sh: baselines, smooth and manufactured
# solutions, grid crossing, the stability map, work-precision, other codes), into results/studies/ and the
# report's second part; builds only what they run (study_programs), timed (results/studies_budget.csv).
studies: configure
	@bash verification/make_studies.sh $(BUILD_DIR) $(JOBS)

# Mutation testing (tests/mutants/run.py): each mutant of tests/mutants/mutants.tsv applied to a copy of
# the tree in $(BUILD_DIR)/mutants/, rebuilt and tested; fates in results/mutants/. At most 2 copies
# side by side (each compiles on one core; the survivors' rebuilds of mpm_tests use JOBS).
MUTANT_JOBS ?= 2
mutants: deps
	@python3 tests/mutants/run.py --build-dir $(BUILD_DIR) --jobs $(MUTANT_JOBS)

bench: build
	@bash benchmarks/run.sh $(BUILD_DIR)

docs: deps
	@bash paper/make_docs.sh $(BUILD_DIR)

clean:
	@rm -rf $(BUILD_DIR) $(SANITIZE_DIR) $(LAB_DIR) runs results
