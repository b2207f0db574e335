# Convenience wrappers around the scripts; CMake (with Ninja) does the real work.
#   make          configure + build the release build in build/ (the CLI is build/foresight)
#   make demo     build and run `build/foresight demo`
#   make test     everything CI checks (scripts/test.sh)
#   make bench    benchmarks with repetitions, and the exact/article ratios (scripts/bench.sh)
#   make clean    remove the build trees

.PHONY: all build demo test bench clean

all: build

build:
	./scripts/build.sh

demo:
	./scripts/demo.sh

test:
	./scripts/test.sh

bench:
	./scripts/bench.sh

clean:
	rm -rf build build-asan build-debug
