#!/usr/bin/env bash
# The Debian packages end to end (issue 22): cpack builds them from this build, lintian checks them (every error or
# warning is fixed or listed in packaging/lintian-accepted.txt), apt-get installs vascusim, the installed
# vascusim-cli prints its version and runs a headless demo (at 256 x 256 x 200: cli_report runs the full-size one
# from the build tree; here the point is that the installed files run the whole pipeline), vascusim-gpu (when built)
# is installed over it and loaded, and both are purged, leaving none of their files. Needs root; skips (exit 77) when
# not root or when a vascusim package is already installed here (the test would replace and purge somebody's
# installation).
# Usage: package_install.sh <build dir> <work dir, created> <source dir>
set -euo pipefail
build=$(realpath "$1") work=$2 source=$(realpath "$3")
skip() { echo "SKIP: $*"; exit 77; }
fail() { echo "FAIL: $*" >&2; exit 1; }

[ "$(id -u)" -eq 0 ] || skip "installing a package needs root"
for package in vascusim vascusim-gpu; do
    if dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
        skip "the package $package is already installed on this machine"
    fi
done
command -v lintian >/dev/null || fail "lintian is missing (scripts/install-deps.sh installs it)"
[ ! -e "$work" ] || [ -z "$(ls -A "$work")" ] || [ -f "$work/.vascusim-package-test" ] ||
    fail "$work holds files this test did not make"
rm -rf "$work" && mkdir -p "$work" && touch "$work/.vascusim-package-test"
work=$(realpath "$work")
cd "$work"

started=$(date +%s)
cpack -G DEB --config "$build/CPackConfig.cmake" -B "$work/packages" > cpack.log 2>&1 || { cat cpack.log; fail "cpack failed"; }
main_package=$(ls "$work"/packages/vascusim_*.deb)
gpu_package=$(ls "$work"/packages/vascusim-gpu_*.deb 2>/dev/null || true)
echo "packages built in $(( $(date +%s) - started )) s:"
for deb in $main_package $gpu_package; do
    echo "  $(basename "$deb"): $(du -k "$deb" | cut -f1) KiB"
    dpkg-deb --field "$deb" Package Version Section Depends | sed 's/^/    /'
done

# lintian: every error (E:) and warning (W:) is either fixed or listed, with the reason, in lintian-accepted.txt.
lintian --no-cfg --fail-on none $main_package $gpu_package > lintian.log 2>&1 || true
accepted=$( (grep -v -E '^\s*(#|$)' "$source/packaging/lintian-accepted.txt" || true) | awk '{print $1}' | sort -u)
unexpected=$(grep -E '^[EW]: ' lintian.log | awk '{print $3}' | sort -u | comm -23 - <(echo "$accepted") || true)
echo "lintian: $(grep -c -E '^E: ' lintian.log || true) errors, $(grep -c -E '^W: ' lintian.log || true) warnings (all listed)"
[ -z "$unexpected" ] || { cat lintian.log; fail "lintian findings not in packaging/lintian-accepted.txt: $unexpected"; }
grep -E '^[EW]: ' lintian.log | sed 's/^/  /' || true

purge() { apt-get purge -y -qq vascusim-gpu vascusim > purge.log 2>&1 || true; }
trap purge EXIT
export DEBIAN_FRONTEND=noninteractive
apt-get install -y -qq --no-install-recommends "$main_package" > install.log 2>&1 || { cat install.log; fail "apt-get install failed"; }
for file in /usr/bin/vascusim /usr/bin/vascusim-cli /usr/share/applications/vascusim.desktop \
            /usr/share/metainfo/org.vascusim.VascuSim.metainfo.xml /usr/share/icons/hicolor/scalable/apps/vascusim.svg \
            /usr/share/man/man1/vascusim-cli.1.gz /usr/share/doc/vascusim/copyright; do
    [ -e "$file" ] || fail "the package did not install $file"
done
for binary in /usr/bin/vascusim /usr/bin/vascusim-cli; do
    ! ldd "$binary" | grep -q "not found" || { ldd "$binary" | grep "not found"; fail "$binary misses libraries"; }
done

# From the installed files only: a clean environment, outside the build and source trees.
installed() { (cd "$work" && env -i PATH=/usr/bin:/bin HOME="$work/home" LANG=C.UTF-8 "$@"); }
installed vascusim-cli --version | tee version.txt
grep -q "^VascuSim " version.txt || fail "--version did not name VascuSim"
grep -q "^GPU plugin not installed" version.txt || fail "without vascusim-gpu the plugin should read 'not installed'"
started=$(date +%s)
installed vascusim-cli demo --out "$work/demo" --size 256x256x200 > demo.json 2> demo.log ||
    { tail -20 demo.log; fail "the installed vascusim-cli demo failed"; }
echo "installed demo: $(( $(date +%s) - started )) s"
for kind in aaa hepatic-tree stenosis; do
    [ -s "$work/demo/$kind/report.pdf" ] || fail "the installed demo wrote no $kind report"
done
installed env QT_QPA_PLATFORM=offscreen vascusim --help > gui-help.txt 2>&1 || { cat gui-help.txt; fail "vascusim --help failed"; }

if [ -n "$gpu_package" ]; then
    apt-get install -y -qq "$gpu_package" > install-gpu.log 2>&1 || { cat install-gpu.log; fail "installing vascusim-gpu failed"; }
    installed vascusim-cli --version | tee version-gpu.txt
    grep -q "^GPU plugin loaded from /usr/lib/x86_64-linux-gnu/vascusim/libvascusim-gpu.so" version-gpu.txt ||
        fail "the installed vascusim-cli did not load the installed plugin"
    ! ldd /usr/lib/x86_64-linux-gnu/vascusim/libvascusim-gpu.so | grep -E -q "libcud|not found" ||
        fail "the plugin should need no CUDA library file (the runtime is linked in; the driver is opened at run time)"
fi

purge
trap - EXIT
for package in vascusim vascusim-gpu; do
    ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "installed" || fail "$package is still installed"
done
for file in /usr/bin/vascusim /usr/bin/vascusim-cli /usr/lib/x86_64-linux-gnu/vascusim /usr/share/doc/vascusim; do
    [ ! -e "$file" ] || fail "purging left $file"
done
echo "PASS: built, checked, installed, ran and purged"
