#!/usr/bin/env bash
# Installs what is missing, builds, and starts the SAASGAPS service on 127.0.0.1:8080 with its SQLite
# database in var/saasgaps.db. Arguments pass through to `saasgaps serve`, e.g.
#   ./deploy/run.sh --port 9000 --workers 2
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

install_packages "${BUILD_PACKAGES[@]}" "${EXAMPLE_PACKAGES[@]}"
build_project saasgaps
mkdir -p "$SAASGAPS_ROOT/var"
exec "$SAASGAPS_BUILD/saasgaps" serve --db "$SAASGAPS_ROOT/var/saasgaps.db" "$@"
