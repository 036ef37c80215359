#!/usr/bin/env python3
"""Checks a demo study's report as a reader would (issue 7, must-show 1-4): every metric of metrics.json is in the
PDF's text with its unit; the numbers equal the runs' own metrics (rounded to the digits printed); metrics.csv holds
the same rows; pdftoppm renders every page; the DICOM Encapsulated PDF has the study's Study Instance UID in a new
series. With --anonymized: no patient identifier of the study in the PDF text nor in the DICOM.

The 3D snapshots (--figures N) are pictures in the PDF when there is a display, else the report says why not.

usage: check_report.py CASE_FOLDER STUDY_BUNDLE [--figures N] [--anonymized PDF DCM] [--run-metrics FILE [--keys K,...]]"""

import csv
import json
import math
import os
import subprocess
import sys
import tempfile


def fail(message):
    print("check_report: " + message, file=sys.stderr)
    sys.exit(1)


def text_of(pdf):
    return subprocess.run(["pdftotext", "-raw", pdf, "-"], check=True, capture_output=True, text=True).stdout


def pages_of(pdf):
    info = subprocess.run(["pdfinfo", pdf], check=True, capture_output=True, text=True).stdout
    return int(next(line.split()[1] for line in info.splitlines() if line.startswith("Pages:")))


def dump_of(dcm):
    return subprocess.run(["dcmdump", "+P", "0008,0016", "+P", "0008,0060", "+P", "0010,0010", "+P", "0010,0020",
                           "+P", "0010,0030", "+P", "0020,000d", "+P", "0020,000e", "+P", "0042,0012", dcm],
                          check=True, capture_output=True, text=True).stdout


def dicom_value(dump, tag):
    for line in dump.splitlines():
        if line.startswith("(" + tag + ")"):
            start, end = line.find("["), line.find("]")
            return line[start + 1:end] if start >= 0 else ""
    return None


def printed_rounds(text, value):
    """The printed figure is its value rounded to the digits printed (half a unit of the last digit)."""
    if "e" in text.lower():
        return math.isclose(float(text), value, rel_tol=5e-4, abs_tol=1e-12)
    decimals = len(text.split(".")[1]) if "." in text else 0
    return abs(float(text) - value) <= 0.5 * 10 ** -decimals * (1 + 1e-9) + 1e-12


def main():
    folder, bundle = sys.argv[1], sys.argv[2]
    study = json.load(open(os.path.join(bundle, "study.json")))
    metadata = study.get("metadata", {})
    pdf, dcm = os.path.join(folder, "report.pdf"), os.path.join(folder, "report.dcm")
    report = json.load(open(os.path.join(folder, "metrics.json")))
    text = " ".join(text_of(pdf).split())

    # 1. Every metric with its unit, as printed.
    for m in report["metrics"]:
        printed = m["text"] + (" " + m["unit"] if m["unit"] else "")
        if printed not in text:
            fail(f"'{m['label']}' = '{printed}' is not in the PDF text")
        if m["text"] != "n/a" and not printed_rounds(m["text"], m["value"]):
            fail(f"{m['key']}: printed {m['text']} is not its value {m['value']} rounded")
    # ... and they equal the runs' own metrics.
    if "--run-metrics" in sys.argv:
        run = json.load(open(sys.argv[sys.argv.index("--run-metrics") + 1]))
        run = run.get("metrics", run)
        keys = sys.argv[sys.argv.index("--keys") + 1].split(",") if "--keys" in sys.argv else None
        compared = 0
        for m in report["metrics"]:
            if m["key"] in run and (keys is None or m["key"] in keys):
                scale = 100.0 if m["unit"] == "%" and (m["key"].endswith("fraction")) else 1.0
                if not math.isclose(m["value"], scale * run[m["key"]], rel_tol=1e-9, abs_tol=1e-12):
                    fail(f"{m['key']}: report {m['value']}, run {run[m['key']]}")
                compared += 1
        if compared < (len(keys) if keys else 5):
            fail(f"only {compared} report metrics found in the run's metrics")
    for analysis in report["not_run"]:
        if " ".join(analysis.split()) not in text:
            fail("the analysis not run is not said: " + analysis)

    # 4. The CSV holds the JSON's rows.
    rows = list(csv.DictReader(open(os.path.join(folder, "metrics.csv"))))
    if [(r["section"], r["key"], r["text"]) for r in rows] != [(m["section"], m["key"], m["text"]) for m in report["metrics"]]:
        fail("metrics.csv and metrics.json differ")

    # The 3D snapshots: pictures with a display (xvfb-run), a note without.
    figures = int(sys.argv[sys.argv.index("--figures") + 1]) if "--figures" in sys.argv else 0
    listed = subprocess.run(["pdfimages", "-list", pdf], check=True, capture_output=True, text=True).stdout
    images = len(listed.splitlines()) - 2
    if os.environ.get("DISPLAY"):
        if images != figures:
            fail(f"{images} pictures in the PDF, expected {figures} snapshots")
    elif figures and text.count("not rendered (3D snapshots need a display") != figures:
        fail("without a display the report must say that its snapshots were not rendered")

    # Every page renders.
    pages = pages_of(pdf)
    with tempfile.TemporaryDirectory() as images:
        subprocess.run(["pdftoppm", "-r", "40", "-png", pdf, os.path.join(images, "page")], check=True)
        rendered = sorted(f for f in os.listdir(images) if f.endswith(".png"))
        if len(rendered) != pages or any(os.path.getsize(os.path.join(images, f)) < 2000 for f in rendered):
            fail(f"pdftoppm rendered {len(rendered)} of {pages} pages (or a blank one)")

    # 2. The DICOM instance: the study's Study Instance UID, a new series, the PDF.
    dump = dump_of(dcm)
    if dicom_value(dump, "0008,0016") is None or "EncapsulatedPDF" not in dump:
        fail("report.dcm is not an Encapsulated PDF instance:\n" + dump)
    if dicom_value(dump, "0020,000d") != metadata.get("study_instance_uid"):
        fail("report.dcm is not in the study's Study Instance UID")
    series = dicom_value(dump, "0020,000e")
    if not series or any(a.get("attributes", {}).get("series_instance_uid") == series for a in study["artifacts"]):
        fail("report.dcm is not in a new series")
    if dicom_value(dump, "0008,0060") != "DOC" or dicom_value(dump, "0042,0012") != "application/pdf":
        fail("report.dcm: modality or MIME type wrong")

    # 3. Anonymized: no identifier of the patient anywhere.
    if "--anonymized" in sys.argv:
        at = sys.argv.index("--anonymized")
        anonymous_pdf, anonymous_dcm = sys.argv[at + 1], sys.argv[at + 2]
        anonymous_text = text_of(anonymous_pdf)
        anonymous_dump = subprocess.run(["dcmdump", anonymous_dcm], check=True, capture_output=True,
                                        text=True).stdout
        identifiers = [metadata.get(k, "") for k in ("patient_name", "patient_id", "patient_birth_date")]
        identifiers += [metadata.get("patient_name", "").replace("^", " ")]
        birth = metadata.get("patient_birth_date", "")
        if len(birth) == 8:
            identifiers.append(f"{birth[0:4]}-{birth[4:6]}-{birth[6:8]}")
        for identifier in filter(None, identifiers):
            if identifier in anonymous_text or identifier in anonymous_dump:
                fail(f"the anonymized report still holds '{identifier}'")
        # Its own new study: the patient's study UID would link it back (pacs store keeps it out of that study).
        if "anonymized" not in anonymous_text or dicom_value(dump_of(anonymous_dcm), "0020,000d") == metadata.get("study_instance_uid") \
                or dicom_value(anonymous_dump, "0012,0062") != "YES":
            fail("the anonymized report does not say so, kept the patient's study UID, or lacks Patient Identity Removed")
    print(f"check_report: {folder}: {len(report['metrics'])} metrics, {pages} pages, DICOM series {series}")


main()
