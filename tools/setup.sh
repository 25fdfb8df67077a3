#!/usr/bin/env bash
# Installs, with apt-get, the Debian packages silodem needs that are missing. Idempotent:
# a package already installed is not touched, and apt-get update runs only if something is missing.
set -euo pipefail
# The solver and its tests; the three reference codes the harness compares with (lammps: lmp,
# liggghts, yade: run as a Python module under /usr/bin/python3.11); matplotlib for report plots;
# Slurm and munge for the sweep's Slurm executor (a one-node cluster, tools/slurm_local.sh);
# python3-paraview for VTK's own reader, which the tests read the VTK frames back with (python3-vtk9
# holds the same modules and conflicts with it). libopenmpi-dev for silodem-mpi (the MPI headers;
# mpirun itself comes with lammps).
packages=(build-essential cmake libeigen3-dev nlohmann-json3-dev libgtest-dev googletest python3-matplotlib
          zlib1g-dev lammps liggghts yade python3.11 slurm-wlm munge python3-paraview libopenmpi-dev)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}" >&2
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${missing[@]}" >/dev/null
fi
