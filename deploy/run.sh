#!/usr/bin/env bash
# Installs what is missing, builds, and runs the report's Problem 3 (case 1) as a worked example.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

install_packages "${BUILD_PACKAGES[@]}"
build_project saasgaps
exec "$SAASGAPS_BUILD/saasgaps" solve "$SAASGAPS_ROOT/schemas/examples/report-problem3-case1.json" \
  -o "$SAASGAPS_BUILD/report-problem3-case1.result.json" "$@"
