# The two commands: `make run` and `make test`. Both install what is missing first.
BUILD ?= build
JOBS ?= 2
CMAKE_FLAGS ?=

.PHONY: all deps configure build run test asan bench bench-peer piglit clean

all: build

deps:
	@bash scripts/deps.sh

configure: deps
	@cmake -S . -B $(BUILD) -G Ninja -DCMAKE_BUILD_TYPE=Release \
	  -DCMAKE_CXX_COMPILER_LAUNCHER=$$(command -v ccache || true) $(CMAKE_FLAGS) >/dev/null

build: configure
	@cmake --build $(BUILD) -j $(JOBS)

# Builds only the tessel command: a newcomer waits for the first picture, not for the tests.
run: configure
	@cmake --build $(BUILD) -j $(JOBS) --target tessel
	@mkdir -p out
	@$(BUILD)/apps/tessel render --size 1280x720 -o out/demo.png --stats

test: build
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

# The robustness tests again under AddressSanitizer + UndefinedBehaviorSanitizer.
asan: deps
	@cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTESSEL_SANITIZE=ON \
	  -DTESSEL_BUILD_BENCH=OFF -DCMAKE_CXX_COMPILER_LAUNCHER=$$(command -v ccache || true) >/dev/null
	@cmake --build build-asan -j $(JOBS)
	@cd build-asan && ctest --output-on-failure -j $(JOBS) -L asan

# Micro-benchmarks of each pipeline stage (Google Benchmark).
bench: build
	@$(BUILD)/bench/tessel_bench_micro

# The standard scenes on Tessel and on Mesa llvmpipe, side by side (README, Performance).
bench-peer: build
	@mkdir -p out/bench
	@$(BUILD)/apps/tessel bench --peer --images out/bench --json out/bench/bench.json

# piglit's GLSL 1.10-3.30 shader_test files through tessel::glsl (docs/glsl.md has the counts).
PIGLIT ?= /usr/lib/x86_64-linux-gnu/piglit
piglit: configure
	@dpkg-query -W piglit >/dev/null 2>&1 || \
	  $$([ "$$(id -u)" -ne 0 ] && echo sudo) apt-get install -y -qq --no-install-recommends piglit >/dev/null
	@cmake --build $(BUILD) -j $(JOBS) --target tessel_piglit
	@$(BUILD)/tests/tessel_piglit $(foreach v,1.10 1.20 1.30 1.40 1.50 3.30,$(wildcard $(PIGLIT)/tests/spec/glsl-$(v) $(PIGLIT)/generated_tests/spec/glsl-$(v)))

clean:
	rm -rf $(BUILD) build-asan out
