# Thin wrapper: everything real lives in CMake (build, tests) and verification/ (figures).
BUILD_DIR ?= build
JOBS      ?= $(shell nproc)

.PHONY: deps build test figures bench docs clean

deps:
	@bash .ci/install-deps.sh

build: deps
	@mkdir -p $(BUILD_DIR)
	@cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release > $(BUILD_DIR)/configure.log 2>&1 || (cat $(BUILD_DIR)/configure.log; exit 1)
	@cmake --build $(BUILD_DIR) -j $(JOBS)

test: build
	@cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)

figures: build
	@bash verification/make_figures.sh $(BUILD_DIR)

bench: build
	@bash benchmarks/run.sh $(BUILD_DIR)

docs: deps
	@bash paper/make_docs.sh $(BUILD_DIR)

clean:
	@rm -rf $(BUILD_DIR) runs results
