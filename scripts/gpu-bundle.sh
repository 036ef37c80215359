#!/usr/bin/env bash
# Collects the GPU test and benchmark binaries with the shared libraries they need (Qt Core/Test and theirs,
# not the C runtime) into .dev/gpu/, for the accelerator machine, which has the CUDA driver but no Qt.
# Usage: scripts/gpu-bundle.sh [build dir] [regex of binary names, e.g. 'fem' (the whole set is over the device
# tool's 64 MiB)]; then on the accelerator: LD_LIBRARY_PATH=.dev/gpu/lib .dev/gpu/<test>
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/default}
only=${2:-.}
out=.dev/gpu
rm -rf "$out" && mkdir -p "$out/lib"
binaries=$(find "$build/tests/gpu" "$build/tests/bench" -maxdepth 2 -type f -executable -name 'tst_*' -o -type f -executable -name 'bench_*' 2>/dev/null | grep -E '(gpu|cuda)' | grep -E "$only" || true)
[ -n "$binaries" ] || { echo "gpu-bundle: no GPU binaries under $build (configure with VSIM_CUDA=ON)" >&2; exit 1; }
for binary in $binaries; do
    cp "$binary" "$out/"
    ldd "$binary" | awk '/=> \// {print $3}' | grep -v -E '/(libc|libm|libgcc_s|libstdc\+\+|libpthread|libdl|librt)\.so' |
        xargs -r -I{} cp -L -n {} "$out/lib/"
done
# The GPU plugin and its libraries (tst_gpu_plugin loads it from $VASCUSIM_GPU_PLUGIN=.dev/gpu/libvascusim-gpu.so).
# The newest one: an older build layout may have left a stale copy beside it (lib/vascusim/ before lib/<triplet>/).
plugin=$(find "$build/lib" -name libvascusim-gpu.so -printf '%T@ %p\n' 2>/dev/null | sort -nr | head -1 | cut -d' ' -f2-)
if [ -n "$plugin" ]; then
    cp "$plugin" "$out/"
    ldd "$plugin" | awk '/=> \// {print $3}' | grep -v -E '/(libc|libm|libgcc_s|libstdc\+\+|libpthread|libdl|librt)\.so' |
        xargs -r -I{} cp -L -n {} "$out/lib/"
fi
du -sh "$out"
# The GPU tests need no fast BLAS (SuiteSparse's CPU solves are not what they measure): the reference BLAS and
# LAPACK instead of OpenBLAS (36 MB) keep the bundle under the device tool's 64 MiB.
reference=/usr/lib/x86_64-linux-gnu
if [ -f "$out/lib/libopenblas.so.0" ] && [ -f "$reference/blas/libblas.so.3" ] && [ -f "$reference/lapack/liblapack.so.3" ]; then
    cp -L "$reference/blas/libblas.so.3" "$out/lib/libblas.so.3"
    cp -L "$reference/lapack/liblapack.so.3" "$out/lib/liblapack.so.3"
    rm -f "$out/lib/libopenblas.so.0"
    du -sh "$out"
fi
