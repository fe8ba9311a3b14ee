#!/usr/bin/env python3
"""Rewrites a native mrpt_fog CSV (time_s, rate_<a>_dph, temp_<name>_C, ...) in a logger's own
layout, independently of the C++ readers: other column names, time in ms, rates in deg/s,
temperatures in C or K, a delimiter of choice, quoted header cells, an extra status column and
preamble lines. It also writes the same rows in the native format (the lines copied verbatim),
so that both files hold the same samples.

  vendor_layout.py IN.csv[.gz] --native OUT_native.csv --vendor OUT_vendor.csv
                   [--every N] [--temp-unit C|K] [--delimiter ';'] [--preamble N] [--format OUT.yaml]

--every N keeps every N-th data row. --format writes the matching format file.
"""
import argparse
import gzip
import sys

AXES = "xyz"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("input")
    ap.add_argument("--native", required=True)
    ap.add_argument("--vendor", required=True)
    ap.add_argument("--format")
    ap.add_argument("--every", type=int, default=1)
    ap.add_argument("--temp-unit", choices=["C", "K"], default="K")
    ap.add_argument("--delimiter", default=";")
    ap.add_argument("--preamble", type=int, default=2)
    ap.add_argument("--max-rows", type=int, default=0, help="stop after this many kept rows (0: all)")
    ap.add_argument("--average", action="store_true",
                    help="each kept row is the mean of its --every rows (time: the block's mean; power: "
                         "its minimum; empty cells left out), as a logger averaging its samples")
    ap.add_argument("--logger-digits", action="store_true",
                    help="print as a logger would (integer ms, 7 significant digits of rate, 0.01 C) "
                         "instead of every digit")
    a = ap.parse_args()

    opener = gzip.open if a.input.endswith(".gz") else open
    meta, body, kept, block = [], [], [], []

    def mean_row(rows):
        cells = []
        for j, name in enumerate(body[0].split(",")):
            vals = [float(r[j]) for r in rows if r[j] != ""]
            if name == "power":
                cells.append("%d" % min(vals))
            elif not vals or (name.startswith("rate_") and any(r[j] == "" for r in rows)):
                cells.append("")  # a gyro-off sample in the block: no rate
            else:
                cells.append(repr(sum(vals) / len(vals)))
        return ",".join(cells)

    with opener(a.input, "rt", newline="") as f:
        k = 0
        for line in f:
            line = line.rstrip("\r\n")
            if line.startswith("#"):
                meta.append(line)
            elif not body:
                body.append(line)
            elif line:
                if a.average:
                    block.append(line.split(","))
                    if len(block) == a.every:
                        kept.append(mean_row(block))
                        block = []
                elif k % a.every == 0:
                    kept.append(line)
                if a.max_rows and len(kept) >= a.max_rows:
                    break
                k += 1
    header = body[0].split(",")

    with open(a.native, "w", newline="") as f:
        f.write("\n".join(meta + [body[0]] + kept) + "\n")

    # The vendor's column names, in the vendor's order: status first, then time, rates, temperatures.
    def vendor_name(col):
        if col == "time_s":
            return "Time [ms]"
        if col.startswith("rate_") and col.endswith("_dph"):
            return "Gyro %s [deg/s]" % col[5].upper()
        if col.startswith("temp_") and col.endswith("_C"):
            return "%s [%s]" % (col[5:-2], "degC" if a.temp_unit == "C" else "K")
        if col == "table_rate_dph":
            return "Table [deg/s]"
        if col == "power":
            return "PWR"
        if col == "field_uT":
            return "B [uT]"
        sys.exit("vendor_layout.py: unknown native column " + col)

    def convert(col, cell):
        if cell == "":
            return ""
        v = float(cell)
        if col == "power":
            return "%d" % int(v)
        if col == "time_s":
            v = v * 1000.0
            if a.logger_digits:
                return "%d" % round(v)
        elif col.endswith("_dph"):
            v = v / 3600.0
            if a.logger_digits:
                return "%.7g" % v
        elif col.startswith("temp_"):
            if a.temp_unit == "K":
                v = v + 273.15
            if a.logger_digits:
                return "%.2f" % v
        return repr(v)

    d = a.delimiter
    names = ["Status"] + [vendor_name(c) for c in header]
    with open(a.vendor, "w", newline="") as f:
        for i in range(a.preamble):
            f.write("Logger export line %d (ignored)\r\n" % (i + 1))
        f.write(d.join('"%s"' % n for n in names) + "\r\n")
        for k, r in enumerate(kept):
            cells = r.split(",")
            status = '"ok"' if k % 7 else '"ok%s checked"' % d  # a quoted cell holding the delimiter
            f.write(d.join([status] + [convert(c, x) for c, x in zip(header, cells)]) + "\r\n")

    if a.format:
        sensor, meta_out, therm = "FOG", [], {}
        for m in meta:
            body_ = m[1:].strip()
            if ":" not in body_:
                continue
            k, v = [s.strip() for s in body_.split(":", 1)]
            if k == "sensor":
                sensor = v
            elif k.startswith("thermistor "):
                attrs = dict(t.split("=") for t in v.split())
                therm[k[len("thermistor "):]] = attrs
            elif k in ("latitude_deg", "epoch_s"):
                meta_out.append((k, v))
        tu = a.temp_unit
        with open(a.format, "w") as f:
            f.write("delimiter: \"%s\"\nskip_lines: %d\n" % (d, a.preamble))
            f.write("time: {column: \"Time [ms]\", unit: ms}\nrates:\n")
            for c in header:
                if c.startswith("rate_"):
                    f.write("  %s: {column: \"%s\", unit: deg/s}\n" % (c[5], vendor_name(c)))
            f.write("thermistors:\n")
            for c in header:
                if c.startswith("temp_"):
                    n = c[5:-2]
                    t = therm.get(n, {})
                    f.write("  %s: {column: \"%s\", unit: %s, side: %s, angle_deg: %s}\n"
                            % (n, vendor_name(c), tu, t.get("side", "other"), t.get("angle_deg", "0")))
            if "table_rate_dph" in header:
                f.write("table_rate: {column: \"Table [deg/s]\", unit: deg/s}\n")
            if "field_uT" in header:
                f.write("field: {column: \"B [uT]\", unit: uT}\n")
            if "power" in header:
                f.write("power: {column: \"PWR\"}\n")
            f.write("metadata: {sensor: %s%s}\n" % (sensor, "".join(", %s: %s" % kv for kv in meta_out)))


if __name__ == "__main__":
    main()
