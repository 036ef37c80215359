#!/usr/bin/env python3
"""The smoke step's time on an H100, estimated from a profile taken on an H200 (issue 21 names the H100; the device
tool lends H200s). Both are the same GH100 chip with 132 SMs at up to 1.98 GHz; the H200's memory is faster
(4.8 TB/s nominal against the H100 SXM's 3.35). So a kernel bound by its instructions or its latency takes the
same time on both, and one bound by memory takes its bytes over the H100's bandwidth. Each kernel's estimate is the
larger of the two (a roofline with the H200's measured time standing for the compute side):

    t_H100 = max(t_H200, DRAM bytes / (copy rate measured on the H200 x 3.35 / 4.8))

Input: the CSV of
    ncu --clock-control none --cache-control none --metrics gpu__time_duration.sum,dram__bytes.sum --csv \
        --launch-skip 10000 --launch-count 700 bench_smoke_cuda 256 3 1 40
and the H200's copy rate from bench_smoke_cuda's JSON (copy_bandwidth_gb_s). A step runs from one addHeatForces
(coolKernel) to the next. Prints one JSON object per whole step in the profile.

    smoke_h100_estimate.py PROFILE.csv COPY_GB_S
"""
import csv
import json
import sys

NOMINAL_H100_TB_S = 3.35
NOMINAL_H200_TB_S = 4.8
SECONDS = {"ns": 1e-9, "nsecond": 1e-9, "us": 1e-6, "usecond": 1e-6, "ms": 1e-3, "msecond": 1e-3}
BYTES = {"byte": 1.0, "Kbyte": 1e3, "Mbyte": 1e6, "Gbyte": 1e9}


def launches(path):
    """Each profiled launch in order: its kernel's name, seconds and DRAM bytes."""
    with open(path, newline="") as f:  # ncu's own messages ("==PROF== ...") are not quoted
        rows = list(csv.reader(line for line in f if line.startswith('"')))
    header, body = rows[0], rows[1:]
    at = {name: n for n, name in enumerate(header)}
    found = {}
    for row in body:
        launch = found.setdefault(int(row[at["ID"]]), {"name": row[at["Kernel Name"]].split("(")[0]})
        unit, value = row[at["Metric Unit"]], float(row[at["Metric Value"]].replace(",", ""))
        if row[at["Metric Name"]] == "gpu__time_duration.sum":
            launch["seconds"] = value * SECONDS[unit]
        elif row[at["Metric Name"]] == "dram__bytes.sum":
            launch["bytes"] = value * BYTES[unit]
    return [found[key] for key in sorted(found)]


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    profile, copy_gb_s = launches(sys.argv[1]), float(sys.argv[2])
    h100_bytes_per_s = copy_gb_s * 1e9 * NOMINAL_H100_TB_S / NOMINAL_H200_TB_S
    starts = [n for n, launch in enumerate(profile) if "coolKernel" in launch["name"]]
    if len(starts) < 2:
        sys.exit("smoke_h100_estimate: the profile holds no whole step (two addHeatForces launches)")
    for first, end in zip(starts, starts[1:]):
        step = profile[first:end]
        h200 = sum(launch["seconds"] for launch in step)
        memory = [launch["bytes"] / h100_bytes_per_s for launch in step]
        h100 = sum(max(launch["seconds"], m) for launch, m in zip(step, memory))
        print(json.dumps({
            "launches": len(step),
            "kernel_seconds_h200": round(h200, 6),
            "dram_gb": round(sum(launch["bytes"] for launch in step) / 1e9, 2),
            "h100_bandwidth_gb_s": round(h100_bytes_per_s / 1e9),
            "kernels_memory_bound_on_h100": sum(1 for launch, m in zip(step, memory) if m > launch["seconds"]),
            "kernel_seconds_h100_estimate": round(h100, 6),
        }))


if __name__ == "__main__":
    main()
