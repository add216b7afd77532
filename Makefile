# bounce: the two commands are `make demo` and `make test`.
#   make        configure + build (CLI at build/bin/bounce, Python at build/python)
#   make test   install missing Debian packages, build, run every C++ and Python test
#   make demo   install missing Debian packages, build, run the main job into out/
#   make bench  build and run the benchmarks (not part of `make test`)
#   make check-long  opt-in long sweeps (results recorded in docs/)
#   make lint        opt-in: functions over 60 lines, files over 400 (clang-tidy), layering

BUILD_DIR ?= build
JOBS      ?= $(shell nproc 2>/dev/null || echo 2)
WERROR    ?= ON
PYTHON    := /usr/bin/python3
CMAKE_FLAGS ?=

.PHONY: all build deps configure test demo bench check-long lint clean

all: build

deps:
	@./scripts/install-deps.sh

$(BUILD_DIR)/CMakeCache.txt:
	cmake -S . -B $(BUILD_DIR) -G Ninja -DCMAKE_BUILD_TYPE=Release \
	  -DBOUNCE_WERROR=$(WERROR) -DPython3_EXECUTABLE=$(PYTHON) $(CMAKE_FLAGS)

configure: $(BUILD_DIR)/CMakeCache.txt

build: configure
	cmake --build $(BUILD_DIR) -j $(JOBS)

test: deps
	@$(MAKE) --no-print-directory build
	cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS) -LE long

demo: deps
	@$(MAKE) --no-print-directory build
	./scripts/demo.sh $(BUILD_DIR)

bench: deps
	@$(MAKE) --no-print-directory build
	./scripts/bench.sh $(BUILD_DIR)

check-long: deps
	@$(MAKE) --no-print-directory build
	cd $(BUILD_DIR) && ctest --output-on-failure -L long

lint: build
	@./scripts/install-deps.sh clang-tidy
	$(PYTHON) tools/check_layers.py
	./tools/check_sizes.sh $(BUILD_DIR)

clean:
	rm -rf $(BUILD_DIR) out
