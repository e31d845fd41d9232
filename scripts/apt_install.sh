#!/usr/bin/env bash
# Installs the given Debian packages that are missing (apt-get; sudo when not root). Quiet and
# idempotent. `--base` adds what every roughgas build needs (the list is kept here only).
# Usage: scripts/apt_install.sh [--base] [PACKAGE]...
set -euo pipefail
for a in "$@"; do
  case "$a" in -h | --help) sed -n '2,/^[^#]/s/^# \{0,1\}//p' "$0"; exit 0 ;; esac
done
base=(g++ cmake make ninja-build pkg-config libeigen3-dev libfftw3-dev libboost-dev libboost-math-dev
      libgtest-dev libbenchmark-dev libtomlplusplus-dev libcli11-dev libfmt-dev
      libopenmpi-dev openmpi-bin libhdf5-dev python3-numpy python3-matplotlib python3-h5py
      pybind11-dev python3-pybind11 python3-dev python3-pytest python3-venv python3-setuptools python3-wheel)
packages=()
for a in "$@"; do
  if [ "$a" = --base ]; then packages+=("${base[@]}"); else packages+=("$a"); fi
done
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "apt_install: installing ${missing[*]}" >&2
  sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
