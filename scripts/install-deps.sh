#!/usr/bin/env bash
# Installs every Debian 12 package the node, its tests and benchmarks need (root or sudo).
set -euo pipefail
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
PKGS=(build-essential cmake pkg-config git ccache
  libeigen3-dev libasio-dev libstb-dev libgdal-dev libtinyobjloader-dev libtomlplusplus-dev
  nlohmann-json3-dev libcli11-dev libspdlog-dev
  libosmesa6-dev libgl-dev libglfw3-dev xvfb xauth libspnav-dev xdotool x11-utils imagemagick libx11-dev
  libgtest-dev libgmock-dev libbenchmark-dev libbullet-dev libfcl-dev gnuplot-nox
  gdal-bin python3-gdal python3-numpy
  tshark iproute2 smcroute libpcap-dev
  clang libclang-rt-14-dev)  # clang + libFuzzer: scripts/fuzz.sh
missing=()
for p in "${PKGS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "install-deps: installing ${missing[*]}"
  $SUDO apt-get update -q
  # tshark asks whether non-root users may capture; answer no, without a prompt.
  echo "wireshark-common wireshark-common/install-setuid boolean false" | $SUDO debconf-set-selections
  $SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -q "${missing[@]}"
fi
# node + npm run the open-dis interop tests; Debian's nodejs/npm when none is installed.
if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then
  $SUDO apt-get update -q
  $SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -q nodejs npm
fi
