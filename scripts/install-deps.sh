#!/usr/bin/env bash
# Installs colza's build and test dependencies from Debian 12's archive (needs root or sudo).
# Set COLZA_WITH_YADE=0 to skip YADE (only the cross-check tests need it).
set -euo pipefail
packages=(cmake g++ make pkg-config git libeigen3-dev libboost-dev libhdf5-dev libtomlplusplus-dev
          libcli11-dev nlohmann-json3-dev libgtest-dev libbenchmark-dev)
if [ "${COLZA_WITH_YADE:-1}" = "1" ]; then packages+=(yade); fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then exit 0; fi
SUDO=""
if [ "$(id -u)" != "0" ]; then SUDO="sudo"; fi
echo "installing: ${missing[*]}"
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
