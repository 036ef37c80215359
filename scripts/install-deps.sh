#!/usr/bin/env bash
# Installs every Debian 12 package VascuSim needs to build, test and run. Idempotent, non-interactive.
# The one list of build and test dependencies: add a package here, nowhere else.
#   --bench  also the reference solvers that only benchmarks use (ctest --preset bench)
set -euo pipefail

PACKAGES=(
    # toolchain
    build-essential cmake ninja-build ccache pkg-config git clang libclang-rt-14-dev
    # the fast linker (cmake/VsimLinker.cmake)
    lld
    # Qt 6 (base, OpenGL widgets, test, linguist tools)
    qt6-base-dev qt6-base-dev-tools libqt6opengl6-dev qt6-tools-dev qt6-tools-dev-tools qt6-l10n-tools
    libgl-dev libglu1-mesa-dev
    # VTK 9.1 (its Qt module is built against Qt 5: never linked), ITK 5.2 (+ gdcm tools, needed by its CMake config)
    libvtk9-dev libinsighttoolkit5-dev libgdcm-dev libgdcm-tools
    # DICOM, linear algebra, JSON
    libdcmtk-dev dcmtk libeigen3-dev nlohmann-json3-dev zlib1g-dev
    # the report's font (embedded in its PDFs); Chinese in the GUI, the views and the report; fontconfig for the views
    fonts-dejavu-core fonts-noto-cjk libfontconfig-dev
    # Qt's own translations (standard buttons, file dialogs) in German and Chinese
    qt6-translations-l10n
    # MP4 movies of a view (the frames are PNG without it)
    ffmpeg
    # headless GUI tests and report checks
    xvfb xauth libgl1-mesa-dri mesa-utils poppler-utils
    # reference tools used by tests and benchmarks
    dcm2niix python3-numpy python3-skimage calculix-ccx
    # a real PACS for the DICOM network tests (started by the tests themselves on loopback ports); openssl makes
    # the certificates of its DICOM TLS test
    orthanc openssl
    # the package test: Debian's package checker on the built .deb
    lintian
    # sparse direct solvers of the wall analysis (CHOLMOD, UMFPACK) and a fast BLAS under them
    libsuitesparse-dev libopenblas0-pthread
)
# reference solvers of the benchmarks only: OpenFOAM v1912 (bench_sph_openfoam)
BENCH_PACKAGES=(openfoam)
case "${1:-}" in
    --bench) PACKAGES+=("${BENCH_PACKAGES[@]}") ;;
    "") ;;
    *) echo "install-deps: unknown option '$1' (--bench)" >&2; exit 2 ;;
esac

missing=()
for package in "${PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
done
if [ ${#missing[@]} -eq 0 ]; then
    echo "install-deps: all ${#PACKAGES[@]} packages present"
    exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null || { echo "install-deps: run as root or install sudo" >&2; exit 1; }
    SUDO="sudo"
fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
