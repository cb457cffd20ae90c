#!/usr/bin/env bash
# Installs what is missing, builds everything, and runs every test (unit, verification, service, and
# slurm: a private one-node Slurm cluster started by tests/slurm/slurm_cluster.sh).
#   ./deploy/test.sh            all tests
#   ./deploy/test.sh -L unit    extra arguments go to ctest
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

install_packages "${BUILD_PACKAGES[@]}" "${EXAMPLE_PACKAGES[@]}" "${TEST_PACKAGES[@]}"
build_project
cd "$SAASGAPS_BUILD"
ctest --output-on-failure --timeout 600 -j "$(nproc)" "$@"
