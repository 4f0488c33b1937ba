#!/usr/bin/env bash
# Install what is missing, then configure (Release) and build dualcontact in
# <repo>/build. Works from any directory.
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$repo"

bash contrib/install_dependencies.sh

# Configuring again is cheap and picks up new source or test files.
echo "build: cmake -S $repo -B $repo/build -DCMAKE_BUILD_TYPE=Release"
cmake -S "$repo" -B "$repo/build" -DCMAKE_BUILD_TYPE=Release
echo "build: cmake --build $repo/build -j$(nproc)"
cmake --build "$repo/build" -j"$(nproc)"
