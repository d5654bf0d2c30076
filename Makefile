# kerf: the two commands of the README.
#   make run   install what is missing, build, run kerf on the bundled examples
#   make test  install what is missing, build, run the whole test suite through ctest
#   make release        the kerf executable link-time optimised, without tests (build-release/)
# and for CI and hardening (fuzz/README.md):
#   make test-sanitize  the whole suite built with ASan + UBSan + _GLIBCXX_ASSERTIONS (build-sanitize/)
#   make fuzz           the libFuzzer targets with clang (build-fuzz/)
# Everything comes from Debian packages; nothing is downloaded at build time.

BUILD_DIR ?= build
BUILD_TYPE ?= Release
CMAKE_FLAGS ?=
SANITIZE_DIR ?= build-sanitize
RELEASE_DIR ?= build-release
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
PACKAGES := g++ make cmake libboost1.81-dev libboost-json1.81-dev libfmt-dev catch2 \
            libcli11-dev libtomlplusplus-dev
SUDO := $(shell [ "$$(id -u)" = 0 ] || echo sudo)

.PHONY: run test build release deps editor-deps vsix clean bench bench-cam fuzz test-sanitize

run: build
	@./scripts/run-examples.sh $(BUILD_DIR)/kerf

# The real-client tests of the language server need Neovim and Node (editor-deps below).
test: deps editor-deps
	cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=$(BUILD_TYPE) -DKERF_EDITOR_TESTS=ON $(CMAKE_FLAGS)
	cmake --build $(BUILD_DIR) -j $(JOBS)
	cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)

build: deps
	cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=$(BUILD_TYPE) $(CMAKE_FLAGS)
	cmake --build $(BUILD_DIR) -j $(JOBS)

# The kerf executable with link-time optimisation (CMakeLists.txt KERF_LTO), without the tests:
# $(RELEASE_DIR)/kerf, the binary to install and to measure (a 100 MB dry run about 13 % faster).
release: deps
	cmake -S . -B $(RELEASE_DIR) -DCMAKE_BUILD_TYPE=Release -DKERF_LTO=ON -DKERF_TESTS=OFF $(CMAKE_FLAGS)
	cmake --build $(RELEASE_DIR) -j $(JOBS) --target kerf

# The same suite under the sanitizers (CMakeLists.txt KERF_SANITIZE). ASan's leak checker stays on;
# halt_on_error makes the first report fail its test.
test-sanitize: deps
	cmake -S . -B $(SANITIZE_DIR) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DKERF_SANITIZE=ON $(CMAKE_FLAGS)
	cmake --build $(SANITIZE_DIR) -j $(JOBS)
	cd $(SANITIZE_DIR) && ASAN_OPTIONS=halt_on_error=1:detect_leaks=1:strict_string_checks=1 \
	  UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 ctest --output-on-failure -j $(JOBS)

# Installs the packages of the list $(1) that are missing (dpkg-query), without prompts.
define install_missing
	@missing=""; for p in $(1); do \
	  dpkg-query -W -f='$${Status}' $$p 2>/dev/null | grep -q "install ok installed" || missing="$$missing $$p"; \
	done; \
	if [ -n "$$missing" ]; then \
	  echo "installing:$$missing"; \
	  $(SUDO) env DEBIAN_FRONTEND=noninteractive apt-get update -qq && \
	  $(SUDO) env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $$missing; \
	fi
endef

deps:
	$(call install_missing,$(PACKAGES))

# What the editor tests need: Neovim (Debian) and Node with npm (Debian's nodejs and npm unless a
# node and npm are already on the PATH, e.g. from NodeSource), then the npm packages of
# editors/vscode exactly as its package-lock.json pins them. --ignore-scripts: no package runs
# code at install time (keytar, an optional dependency of vsce for publishing, is not built).
editor-deps:
	@missing=""; \
	dpkg-query -W -f='$${Status}' neovim 2>/dev/null | grep -q "install ok installed" || missing="$$missing neovim"; \
	command -v node >/dev/null 2>&1 || missing="$$missing nodejs"; \
	command -v npm >/dev/null 2>&1 || missing="$$missing npm"; \
	if [ -n "$$missing" ]; then \
	  echo "installing:$$missing"; \
	  $(SUDO) env DEBIAN_FRONTEND=noninteractive apt-get update -qq && \
	  $(SUDO) env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $$missing; \
	fi
	@if [ ! -f editors/vscode/node_modules/.package-lock.json ] || \
	    [ editors/vscode/package-lock.json -nt editors/vscode/node_modules/.package-lock.json ]; then \
	  cd editors/vscode && npm ci --ignore-scripts --no-audit --no-fund; \
	fi

# The VS Code extension as build/kerf.vsix (install: code --install-extension build/kerf.vsix).
vsix: editor-deps
	cd editors/vscode && node node_modules/typescript/bin/tsc -p . && \
	  node node_modules/@vscode/vsce/vsce package --allow-missing-repository --skip-license --out ../../$(BUILD_DIR)/kerf.vsix

# The parse benchmark (bench/run.sh), then the dry run against LinuxCNC's rs274
# (bench/dryrun_vs_rs274.sh; rs274 comes from linuxcnc-uspace, /usr/bin/time from time), then the
# whole-process figures on short-line CAM output (bench/cam.sh, below).
BENCH_PACKAGES := libbenchmark-dev linuxcnc-uspace time
bench: deps
	$(call install_missing,$(BENCH_PACKAGES))
	cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release -DKERF_BENCH=ON
	cmake --build $(BUILD_DIR) -j $(JOBS) --target kerf_bench kerf_bench_dryrun kerf
	./bench/run.sh $(BUILD_DIR)
	./bench/dryrun_vs_rs274.sh $(BUILD_DIR)
	$(MAKE) release
	./bench/cam.sh $(RELEASE_DIR)

# Whole-process figures of parse, run, check and fmt on gen_program.py's 100 MB mill, lathe and macro
# programs beside rs274, a folder of 10,000 small programs, the corpus's largest files (issue 18;
# inputs under /tmp/kerf-bench-data, KERF_BENCH_DATA moves them; bench/cam.sh says the rest), with
# the release build's kerf (link-time optimised, as installed).
bench-cam: deps release
	$(call install_missing,$(BENCH_PACKAGES))
	./bench/cam.sh $(RELEASE_DIR)

# clang and its libFuzzer runtime (Debian: clang, libclang-rt-14-dev). The targets and how to run
# them: fuzz/README.md.
FUZZ_PACKAGES := clang libclang-rt-14-dev
FUZZ_TARGETS := fuzz_grammar fuzz_interpreter fuzz_analyzer fuzz_formatter fuzz_converter fuzz_machine_toml fuzz_dialect_toml \
                fuzz_input fuzz_kerf_toml fuzz_lsp
fuzz: deps
	$(call install_missing,$(FUZZ_PACKAGES))
	cmake -S . -B build-fuzz -DCMAKE_CXX_COMPILER=clang++ -DKERF_FUZZ=ON -DKERF_TESTS=OFF -DCMAKE_BUILD_TYPE=RelWithDebInfo
	cmake --build build-fuzz -j $(JOBS) --target $(FUZZ_TARGETS)
	python3 fuzz/make_seeds.py build-fuzz/seeds

clean:
	rm -rf $(BUILD_DIR) build-fuzz $(SANITIZE_DIR) $(RELEASE_DIR)
