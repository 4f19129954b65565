# Thin wrapper around CMake/CTest. `make run` and `make test` are the two
# commands of the README; both install missing Debian packages first.
BUILD_DIR ?= build
JOBS ?= $(shell nproc)
SCENE ?= configs/brick_wall.yaml
OUT ?= out/$(basename $(notdir $(SCENE)))
FISSURE = $(BUILD_DIR)/app/fissure

.PHONY: all deps configure build run test bench format clean

all: build

deps:
	@scripts/install-deps.sh

configure: deps
	@cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release > /dev/null

build: configure
	@cmake --build $(BUILD_DIR) -j $(JOBS)

run: build
	$(FISSURE) run $(SCENE) -o $(OUT)
	/usr/bin/python3 scripts/plot_monitors.py $(OUT)

test: build
	ctest --test-dir $(BUILD_DIR) --output-on-failure -j $(JOBS)

bench: build
	benchmarks/run_all.sh $(BUILD_DIR)

format:
	@git ls-files '*.cpp' '*.h' | xargs clang-format -i

clean:
	rm -rf $(BUILD_DIR)
