#!/usr/bin/env bash
# Installs the Debian 12 packages andros-bridge needs to build and test, when
# they are missing. Runs apt-get as root, or through sudo.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libsdl2-dev libyaml-cpp-dev libspdlog-dev libcli11-dev nlohmann-json3-dev libssl-dev
  libcpp-httplib-dev  # the trainer's web server (docs/trainer.md)
  libgtest-dev libgmock-dev python3 groff-base
  fonts-dejavu-core  # the plot's font: tests/cli/check_plot.py measures its labels with it
  ccache  # keeps compiled objects between builds (CMakeLists.txt uses it when installed)
)
packages+=("$@")  # callers ask for more: the test command clang, libFuzzer, clang-format and clang-tidy

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
((${#missing[@]})) || exit 0

as_root=()
if [[ $(id -u) -ne 0 ]]; then
  command -v sudo >/dev/null || { echo "setup: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  as_root=(sudo)
fi
echo "setup: installing ${missing[*]}"
"${as_root[@]}" apt-get update -qq
"${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}"
