# Protocol code generator. Contracts (kept stable, see README): make, make test, make check,
# make audit, make bench, make differential, generated/ir.json, tests/vectors/,
# tests/conformance/{decode,encode}.
SHELL := /bin/bash
PYTHON ?= python3
VENV := .venv
PY := $(VENV)/bin/python
# Every `cmake --build` the tests run (the README recipes use the default generator, which builds one
# file at a time) uses every core; the C++ package is a compiled library since issue 39.
CMAKE_BUILD_PARALLEL_LEVEL ?= $(shell nproc 2>/dev/null || echo 2)
export CMAKE_BUILD_PARALLEL_LEVEL
# The long pytest suites run on pytest-xdist workers, one per core (at most 4), each worker a test
# file at a time (--dist loadfile: a module's fixtures, simulators and builds stay in one worker);
# a tree two workers build takes turns (tests/helpers/builds.py, tests/lang/lock.sh). TEST_JOBS=1
# runs them in one process.
TEST_JOBS ?= $(shell n=$$(nproc 2>/dev/null || echo 1); [ "$$n" -gt 4 ] && n=4; echo $$n)
XDIST := $(if $(filter-out 0 1,$(TEST_JOBS)),-n $(TEST_JOBS) --dist loadfile)
# The language targets: the registry generator/targets/__init__.py (standard library only, so
# the bare $(PYTHON) reads it before .venv exists).
LANGS := $(shell $(PYTHON) -m generator.targets)
ifeq ($(strip $(LANGS)),)
$(error cannot read the language targets: '$(PYTHON) -m generator.targets' failed)
endif
MANUALS ?= ../shared/manuals
CAPTURE ?= ../shared/captures/mip_data.bin
export RUFF := $(abspath $(VENV)/bin/ruff)

SPEC_INPUTS := $(shell find spec generator templates tests/vectors tests/streams tests/sessions -type f -not -name '*.pyc' 2>/dev/null) requirements.txt .clang-format ruff.toml rustfmt.toml VERSION LICENSE

.PHONY: all bootstrap generate golden html test test-generator test-spec test-bench test-export test-golden test-docs test-conformance test-capture test-bigendian test-consumer test-outside test-extras test-cortexm test-release test-mingw test-fuzz-regressions fuzz fuzz-long differential $(addprefix test-,$(LANGS)) check lint audit bench bench-instructions clean distclean

all: generate

# The generator's own tools, pinned (requirements.txt: jinja2, pyyaml, jsonschema, pytest, ruff,
# clang-format, ...). Each failure says the one command that fixes it.
$(VENV)/.stamp: requirements.txt
	@$(PYTHON) -c 'import sys; sys.exit(sys.version_info < (3, 9))' 2>/dev/null || \
	  { echo "error: make needs Python 3.9 or later as '$(PYTHON)'; run: apt-get install python3 (or make PYTHON=/path/to/python3)" >&2; exit 1; }
	@$(PYTHON) -m venv $(VENV) || \
	  { rm -rf $(VENV); echo "error: '$(PYTHON) -m venv' failed; run: apt-get install python3-venv" >&2; exit 1; }
	@$(VENV)/bin/pip install --quiet --disable-pip-version-check -r requirements.txt || \
	  { echo "error: installing requirements.txt into $(VENV) failed (is PyPI reachable?); run: make distclean && make" >&2; exit 1; }
	touch $@

# Regenerate only when an input changed; the generator itself writes only changed files.
# `$(PY) -m generator generate` is the `mipgen generate` command (pip install -e .; README).
generate: build/.generated
build/.generated: $(VENV)/.stamp $(SPEC_INPUTS)
	$(PY) -m generator generate
	@mkdir -p build && touch $@

# What the tests need beyond `make` (cmake, googletest, Chromium, clippy, ...): tools/bootstrap
# installs what is missing (as root) or prints the command that does.
# It runs after .venv exists: it installs requirements-spark.txt (pyspark) there.
bootstrap: $(VENV)/.stamp
	@tools/bootstrap

# Each test target's first line says when it started (CI's log shows where the time goes).
STAMP = @echo "== $@ started $$(date -u +%H:%M:%S) UTC"

test: bootstrap generate test-generator test-spec test-docs $(addprefix test-,$(LANGS)) test-conformance test-capture test-export test-fuzz-regressions test-bench test-golden test-consumer test-outside

# Python everywhere under tests/ is one package (tests/__init__.py): pytest and the scripts run
# from the project root (`python -m tests.conformance.differential`), shared helpers in tests/helpers/.
test-generator: $(VENV)/.stamp
	$(STAMP)
	$(VENV)/bin/ruff check --config ruff.toml generator tests
	$(VENV)/bin/ruff format --config ruff.toml --check --quiet generator tests
	$(PY) -m pytest -q $(XDIST) tests/generator

# The spec against what its manuals state outside the field tables (prose sizes, worked examples).
test-spec: generate
	$(STAMP)
	$(PY) -m pytest -q tests/spec

# The benchmark streams are what their sidecars say (small scale; `make bench` runs the benchmarks).
# The Python packages' user commands (export, info, plot) against the canonical decode.
test-export: generate
	$(STAMP)
	$(PY) -m pytest -q $(XDIST) --durations=10 tests/export

test-bench: generate
	$(STAMP)
	$(PY) -m pytest -q tests/bench

# The golden tree tests/golden/everything/ (the every-feature fixture rendered by every back end:
# the generated files; the runtime copies listed in its RUNTIME_COPIES) equals a fresh rendering
# (build/golden/tree/) byte for byte, and those packages build and pass their own tests (build dirs
# under build/golden/, reused). `make golden` refreshes the tree after a wanted change.
test-golden: $(VENV)/.stamp
	$(STAMP)
	$(PY) -m pytest -q --durations=10 tests/golden

golden: $(VENV)/.stamp
	$(PY) -m tests.golden.refresh

$(addprefix test-,$(LANGS)): test-%: generate
	$(STAMP)
	tests/lang/$*.sh test

# The reference documentation: Markdown links and pages (fast), then the HTML site served on
# localhost and opened in headless Chromium (Debian `chromium`); screenshots go to build/screenshots/.
test-docs: generate
	$(STAMP)
	$(PY) -m pytest -q tests/docs

# The reference documentation as an offline HTML site in build/html/ (open build/html/index.html).
html: generate
	$(PY) -m generator.docs.site --out build/html

test-conformance: generate
	$(STAMP)
	$(PY) -m pytest -q $(XDIST) --durations=15 tests/conformance

# Differential rounds (tests/conformance/differential.py; one round runs in test-conformance):
# hostile values of every layout and corrupted packets through the four languages' CLIs against
# the reference decoder. ROUNDS rounds, seeds SEED, SEED+1, ... (random seeds when SEED is unset);
# each round prints its seed; a failure prints the command that replays it.
ROUNDS ?= 50
differential: generate
	$(PY) -m tests.conformance.differential --rounds $(ROUNDS) $(if $(SEED),--seed $(SEED))

# The device capture decodes completely and identically in the four languages (run when the
# file exists; `make test` says so when it does not).
test-capture: generate
	$(STAMP)
ifneq ($(wildcard $(CAPTURE)),)
	$(PY) tests/conformance/check_capture.py $(CAPTURE)
else
	@echo "test-capture: $(CAPTURE) not found: the device-capture check did not run"
endif

# The C library built for a big-endian host (s390x, run under qemu-user). Not part of `make test`:
# needs gcc-s390x-linux-gnu, libc6-dev-s390x-cross and qemu-user (installed by .ci/run).
test-bigendian: generate
	$(PY) -m pytest -q tests/bigendian

# The C and C++ packages consumed from outside the repository as docs/packaging.md says
# (tests/consumer/): Release -O3 with -Werror under gcc (and clang where installed), the READMEs'
# install recipes (the blocks marked <!-- consumer: install -->, run as they stand) where googletest
# cannot be found (and, for C, no C++ compiler exists) into one prefix, then the READMEs'
# find_package and pkg-config blocks, a versioned find_package, pkg-config (the session API through
# <pkg>-posix), and add_subdirectory into a C-only project (only the linked libraries built). The
# package builds run two at a time, each on every core.
test-consumer: generate
	$(STAMP)
	$(PY) -m pytest -q tests/consumer/test_consumers.py

# The outside user (issue 39; docs/conformance.md §11): every command of every user-facing page
# (README's documentation table, the getting-started pages), taken from the pages' blocks and run
# in a temporary directory outside the repository, with a fresh virtualenv holding the wheels of
# tests/lang/python.sh consumer (reused), the C path with no googletest and no C++ compiler, the
# packages copied out as a user vendors them, cargo offline. A few minutes (the C++ example build
# most of it).
test-outside: generate
	$(STAMP)
	$(PY) -m pytest -q tests/consumer/test_outside_user.py

# Each extra of the Python package alone (issue 50; docs/conformance.md §11 "Each extra alone"):
# `mipcodec[EXTRA]` installed by itself into a fresh virtualenv with uv (pip's stand-in, pinned in
# requirements.txt) from the wheel and PyPI, then the extra's example from the user pages run there
# (tests/consumer/test_extras_alone.py). Not part of `make test` (PyPI); .ci/run runs it. About
# 2 minutes with a cold uv cache (pyspark most of it: its sdist's download and build, about 50 s,
# and the Spark job, 25-50 s), 1 minute warm.
test-extras: generate
	$(PY) -m pytest -q tests/consumer/test_extras_alone.py

# Release checks (docs/versioning.md "Releasing"): the Python packages' sdists and wheels pass
# `twine check --strict` with PyPI's classifiers (tests/consumer/test_release.py), and `cargo publish
# --dry-run` passes for every crate (tests/lang/rust.sh publish; reads the crates.io index). Not
# part of `make test` (the network); .ci/run runs it. About a minute.
test-release: generate
	$(PY) -m pytest -q tests/consumer/test_release.py
	tests/lang/rust.sh publish

# The C core built freestanding for a Cortex-M4F (arm-none-eabi-gcc + newlib, -Os) into a minimal
# image whose code size it prints, and the C package built top-level with only its shipped toolchain
# file (cmake/arm-none-eabi.cmake). Not part of `make test`: needs gcc-arm-none-eabi and
# libnewlib-arm-none-eabi (tools/bootstrap --ci; .ci/run runs it).
test-cortexm: generate
	$(PY) -m pytest -q -s tests/consumer/test_cortexm.py

# The C and C++ packages built for Windows with MinGW-w64 and their shipped toolchain file
# (cmake/x86_64-w64-mingw32.cmake; the Win32 transports), their tools run under Wine: every golden
# vector, the session tool against the simulator over TCP on 127.0.0.1. Not part of `make test`:
# needs gcc-mingw-w64-x86-64, g++-mingw-w64-x86-64 and wine64 (tools/bootstrap --ci; .ci/run runs it).
test-mingw: generate
	$(PY) -m pytest -q tests/consumer/test_mingw.py

# Fuzzing (tests/fuzz/, docs/fuzzing.md): every harness of every language and package, one at a
# time, with a final table (target, executions, exec/s, wall time, findings). A finding fails the
# run; its input is saved under build/fuzz/findings/<lang>/<package>/<target>/. Needs clang-14,
# libclang-rt-14-dev, llvm-14, a nightly Rust toolchain with cargo-fuzz, and atheris (in .venv).
# FUZZ_JOBS runs that many targets at once (default 1: the machine may be shared; CI runs 2).
# FUZZ_ONLY limits the targets: LANG[/PACKAGE[/TARGET]] words, e.g. FUZZ_ONLY="c cpp/mipcodec"; "spec" is
# the generator's front end (tests/fuzz/spec/: spec files through the YAML loader, schema and IR passes).
FUZZ_SECONDS ?= 10
FUZZ_RUNS ?= 10000000
FUZZ_PY_RUNS ?= 1000000
FUZZ_ONLY ?=
FUZZ_JOBS ?= 1
FUZZ_SELECT = $(foreach o,$(FUZZ_ONLY),--only $(o))

fuzz: generate
	$(PY) -m tests.fuzz.fuzz run --seconds $(FUZZ_SECONDS) --jobs $(FUZZ_JOBS) $(FUZZ_SELECT)

fuzz-long: generate
	$(PY) -m tests.fuzz.fuzz run --runs $(FUZZ_RUNS) --python-runs $(FUZZ_PY_RUNS) $(FUZZ_SELECT)

# Part of `make test`: the inputs of tests/fuzz/regressions/ (and the seed corpus) through every
# language's harnesses without clang or libFuzzer (gcc/g++ with ASan+UBSan, cargo test, pytest).
test-fuzz-regressions: generate
	$(STAMP)
	$(PY) -m tests.fuzz.fuzz replay

# Benchmarks of the four languages (tests/bench/run.py, docs/benchmarks.md): builds them into
# build/bench/, runs each in 5 processes (best of 5 passes each) on the streams of
# tests/bench/streams.py, prints one table (Mpkt/s, GB/s, spread, fraction of bulk, decode/frame)
# and writes build/bench/results.json; then the decode CLIs and the compile cost of the C++
# package per translation unit (--compile-only runs only that). BENCH_ARGS passes options, e.g.
# BENCH_ARGS="--langs c,cpp --scale 0.1 --processes 2 --passes 2 --instructions".
# bench-instructions: instructions per packet of C, C++ and Rust frame and decode (callgrind).
BENCH_ARGS ?=
bench: generate
	$(PY) tests/bench/run.py $(BENCH_ARGS)
bench-instructions: generate
	$(PY) tests/bench/run.py --instructions-only --langs c,cpp,rust $(BENCH_ARGS)

# Fails when generated/ (or docs/errata.md) is not what the spec and templates produce.
check: $(VENV)/.stamp
	$(PY) -m generator.drift

# YAML traps (unquoted on/off/yes/no), descriptors without a golden vector, stated lengths.
lint: $(VENV)/.stamp
	$(PY) -m generator lint

# Does the spec cover the manuals (MANUALS=dir): headings, quoted packets, example tables
# (generator/audit.py) and every factory default they state, transcribed or decided
# (generator/defaults_audit.py).
audit: $(VENV)/.stamp
	@status=0; \
	$(PY) -m generator.audit --manuals $(MANUALS) $(if $(KINDS),--kinds $(KINDS)) || status=$$?; \
	$(PY) -m generator.defaults_audit --manuals $(MANUALS) || { s=$$?; [ $$s -gt $$status ] && status=$$s; }; \
	exit $$status

clean:
	rm -rf build

distclean: clean
	rm -rf $(VENV)
