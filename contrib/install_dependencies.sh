#!/usr/bin/env bash
# Install the Debian packages dualcontact needs, but only those that are
# missing: cheap to repeat, nothing is downloaded if all are present.
# Meant for Debian 12 (bookworm); run as root (or with sudo available).
set -euo pipefail

packages=(g++ cmake make libdeal.ii-dev libboost-program-options-dev catch2 numdiff
  openmpi-bin gnuplot-nox)

missing=()
for package in "${packages[@]}"; do
  # dpkg -s also succeeds for removed packages whose config files remain,
  # so look at the status line itself.
  if dpkg -s "$package" 2>/dev/null | grep -q '^Status: install ok installed'; then
    :
  else
    missing+=("$package")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install_dependencies: all packages present (${packages[*]})."
  exit 0
fi

echo "install_dependencies: missing: ${missing[*]}"
if [ "$(id -u)" -eq 0 ]; then
  sudo=()
elif command -v sudo >/dev/null 2>&1; then
  sudo=(sudo)
else
  echo "install_dependencies: not root and no sudo; install them by hand:" >&2
  echo "  apt-get install ${missing[*]}" >&2
  exit 1
fi

echo "install_dependencies: apt-get update"
"${sudo[@]}" apt-get update
echo "install_dependencies: apt-get install -y ${missing[*]}"
"${sudo[@]}" env DEBIAN_FRONTEND=noninteractive \
  apt-get install -y "${missing[@]}"
echo "install_dependencies: done."
