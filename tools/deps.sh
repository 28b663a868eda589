# Sourced by tools/derive and tools/test: makes sure the Debian packages the build needs are there.
# As root it installs what is missing (apt-get update first); as anyone else it prints the exact
# apt-get line and stops.

# billiards-derive runs gappa to prove the fast paths' domains. The manual (docs target) needs doxygen,
# python3 and libjs-mathjax; its browser test, chromium; the audit's JSON Schema test, python3-jsonschema. The
# Python package: pybind11-dev, python3-dev and python3-numpy to build it; python3-pytest and
# python3-distributed (Dask) for its tests; python3-pip and python3-venv for its installation test.
billiards_packages=(cmake make g++ pkg-config clang-format libginac-dev gappa libeigen3-dev catch2 libbenchmark-dev
                    nlohmann-json3-dev libcli11-dev doxygen libjs-mathjax python3 python3-jsonschema chromium
                    pybind11-dev python3-dev python3-numpy python3-pytest python3-distributed python3-pip
                    python3-venv)

billiards_require_packages() {
  local missing=() package
  for package in "${billiards_packages[@]}" "$@"; do
    if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
      missing+=("$package")
    fi
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  if [ "$(id -u)" -eq 0 ]; then
    echo "Installing missing Debian packages: ${missing[*]}"
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq
    apt-get install -y -qq --no-install-recommends "${missing[@]}"
  else
    echo "Missing Debian packages: ${missing[*]}" >&2
    echo "Install them with:" >&2
    echo "  sudo apt-get install -y --no-install-recommends ${missing[*]}" >&2
    exit 1
  fi
}
