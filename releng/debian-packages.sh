#!/usr/bin/env bash
# Installs the Debian packages the C++ side builds on and the tests run with (Boost.Statechart and
# Qt SCXML for the engine's comparison benchmark, GTK, WebKitGTK for
# the help window and the diagram, Xvfb, ImageMagick for screenshots, Chromium for the diagram's
# end-to-end tests), when missing (as root, or through sudo). Used by test.sh and `kse demo`.
set -euo pipefail
packages="g++ cmake ninja-build libprotobuf-dev protobuf-compiler libgtest-dev libgmock-dev libbenchmark-dev
  libboost-dev qt6-scxml-dev
  xvfb xauth x11-utils libgtk-3-0 libwebkit2gtk-4.1-0 imagemagick unzip chromium"
missing=""
for package in $packages; do
  dpkg -s "$package" >/dev/null 2>&1 || missing="$missing $package"
done
[ -z "$missing" ] && exit 0
as_root() { if [ "$(id -u)" = 0 ]; then "$@"; else sudo "$@"; fi; }
echo "== installing Debian packages:$missing" >&2
as_root apt-get update -qq
# shellcheck disable=SC2086
as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $missing >&2
