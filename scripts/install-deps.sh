#!/usr/bin/env bash
# Installs colza's build and test dependencies from Debian 12's archive (needs root or sudo).
# Set COLZA_WITH_YADE=0 to skip YADE (only the cross-check tests need it).
# The plots need python3-matplotlib (a run without it warns and succeeds); the pictures tests
# read results with python3-h5py and VTK's Xdmf reader from python3-paraview (ParaView 5.11's
# own; it replaces python3-vtk9, which lacks that reader). Set COLZA_WITH_PARAVIEW=0 to skip
# python3-paraview (that test is then reported as skipped).
set -euo pipefail
packages=(cmake g++ make pkg-config git libeigen3-dev libboost-dev libhdf5-dev libtomlplusplus-dev
          libcli11-dev nlohmann-json3-dev libgtest-dev libbenchmark-dev
          python3-numpy python3-matplotlib python3-h5py)
if [ "${COLZA_WITH_YADE:-1}" = "1" ]; then packages+=(yade); fi
if [ "${COLZA_WITH_PARAVIEW:-1}" = "1" ]; then packages+=(python3-paraview); fi
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
