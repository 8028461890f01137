#!/usr/bin/env bash
# Brings a fresh machine (or a stale checkout) to a buildable, testable state, doing only what is
# missing or out of date: system packages, npm dependencies, the native build (core + tests),
# the WebAssembly module, the TypeScript package (dist/), and with --web the editor bundle and the
# API reference.
# Idempotent: a run with nothing to do takes a few seconds.
set -euo pipefail
cd "$(dirname "$0")/.."

want_web=0
for arg in "$@"; do
  case "$arg" in
    --web) want_web=1 ;;
    *) echo "setup.sh: unknown option $arg" >&2; exit 2 ;;
  esac
done

step() { printf '\033[1m[setup]\033[0m %s\n' "$*"; }
# Runs an (incremental) cmake build, quiet when there is nothing to do, loud when it fails.
build() {
  local out
  if ! out=$(cmake --build "$1" 2>&1); then
    echo "$out" >&2
    return 1
  fi
  grep -v -e '^ninja: no work to do' -e 'Re-checking globbed directories' <<<"$out" || true
}

# ---- System packages (Debian) -----------------------------------------------------------------
missing=()
command -v cmake >/dev/null || missing+=(cmake)
command -v ninja >/dev/null || missing+=(ninja-build)
command -v g++ >/dev/null || missing+=(g++)
command -v em++ >/dev/null || missing+=(emscripten)
command -v chromium >/dev/null || missing+=(chromium)
command -v clang-format >/dev/null || missing+=(clang-format)
[ -f /usr/include/eigen3/Eigen/Core ] || missing+=(libeigen3-dev)
[ -f /usr/include/gtest/gtest.h ] || missing+=(libgtest-dev)
command -v node >/dev/null || missing+=(nodejs npm)
if [ ${#missing[@]} -gt 0 ]; then
  step "installing system packages: ${missing[*]}"
  sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  # Another apt (an unattended upgrade, a second checkout's setup) may hold the lock: wait for it.
  apt_wait=(-o DPkg::Lock::Timeout=600)
  "${sudo_cmd[@]}" apt-get "${apt_wait[@]}" update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get "${apt_wait[@]}" install -y -qq "${missing[@]}" >/dev/null
fi

# ---- npm dependencies (re-installed when package-lock.json changes) ---------------------------
lock_hash=$(sha256sum package-lock.json | cut -d' ' -f1)
if [ ! -f node_modules/.splinekit-lock ] || [ "$(cat node_modules/.splinekit-lock)" != "$lock_hash" ]; then
  step "npm ci"
  npm ci --no-audit --no-fund --loglevel=error
  echo "$lock_hash" > node_modules/.splinekit-lock
fi

# ---- Native build: core + GoogleTest (ninja rebuilds only what changed) ------------------------
if [ ! -f build/native/build.ninja ]; then
  step "configuring the native build"
  cmake -S . -B build/native -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
build build/native

# ---- WebAssembly module: src/core/splinekit-core.mjs -----------------------------------------
export NODE_PATH=/usr/share/nodejs  # em++ 3.1.6 needs Debian's acorn
if [ ! -f build/wasm/build.ninja ]; then
  step "configuring the WebAssembly build"
  emcmake cmake -S . -B build/wasm -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
build build/wasm

# ---- TypeScript package: dist/ (rebuilt when anything in src/ is newer) ------------------------
stamp=dist/.build-stamp
if [ ! -f "$stamp" ] || [ -n "$(find src tsconfig.json package.json scripts/browser-bundle.config.ts -newer "$stamp" -print -quit)" ]; then
  step "building the TypeScript package (dist/)"
  rm -rf dist
  npx tsc -p tsconfig.json
  cp src/core/splinekit-core.mjs src/core/splinekit-core.d.mts dist/core/
  chmod +x dist/cli/splinekit.js
  # dist/browser/splinekit.js: the package and its dependencies in one ES module for plain pages.
  npx vite build --config scripts/browser-bundle.config.ts
  touch "$stamp"
fi

# ---- Editor bundle: build/web and API reference: build/api (only with --web) ------------------
if [ "$want_web" -eq 1 ]; then
  astamp=build/api/.build-stamp
  if [ ! -f "$astamp" ] || [ -n "$(find src typedoc.json tsconfig.json -newer "$astamp" -print -quit)" ]; then
    # Fails on any exported symbol without a doc comment (typedoc.json: notDocumented, treatWarningsAsErrors).
    step "building the API reference (build/api)"
    npx typedoc --logLevel Warn
    touch "$astamp"
  fi

  wstamp=build/web/.build-stamp
  if [ ! -f "$wstamp" ] || [ -n "$(find src web public -newer "$wstamp" -print -quit)" ]; then
    step "building the editor (build/web)"
    npx vite build --config web/vite.config.ts --logLevel warn
    touch "$wstamp"
  fi
fi
