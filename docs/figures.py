"""The quoted figures of the docs against what their commands printed
(docs/figures.sh runs the commands; this reads docs/figures.map).

    python3 docs/figures.py check VALUES    exit 1 when a quoted figure is off or its sentence is gone
    python3 docs/figures.py update VALUES   rewrite the quoted figures in place, keeping their decimals
                                            (and, with FIGURES_BENCH=yes, the bench table from the CSV)

VALUES holds "key value" lines. The bench's figures come from the committed
docs/bench.csv: bench.SCENE.SIZE.PRESET.{ms,fps,p99,speedup} (speedup: the
reference's time over the preset's), still.SIZE.{ms,full_ms,ratio,self_ms,rest_frames,
rest_ms,rest_ratio,rest_self_ratio} (the dim still frame against a full
night-drive frame and against itself with every stage on every frame), and the bench table quoted in
docs/performance.md is checked row by row against that file. The peers'
figures come from the committed docs/bench-peers.txt (`eyestream bench
--peers`'s table): peers.SCENE.SIZE.{pattanaik,fogglow}.{peer_ms,io_ms,eyestream_ms,ratio,energy}.
"""
import csv
import os
import re
import sys

NUMBER = r"(-?[0-9]+(?:\.[0-9]+)?)"


def bench_values(path="docs/bench.csv"):
    rows = list(csv.DictReader(open(path)))
    values, reference = {}, {}
    for r in rows:
        if r["skip"] == "on" and r["preset"] == "reference":
            reference[(r["scene"], r["size"])] = float(r["filter_ms"])
    for r in rows:
        if r["skip"] != "on" or r["against"] != "reference":
            continue
        key = f"bench.{r['scene']}.{r['size']}.{r['preset']}"
        values[key + ".ms"] = float(r["filter_ms"])
        values[key + ".fps"] = float(r["fps"])
        values[key + ".p99"] = float(r["de2000_p99"])
        values[key + ".speedup"] = reference[(r["scene"], r["size"])] / float(r["filter_ms"])
    # The skip study: the dim still frame (headlights) against a full frame
    # of the other scene, over all its frames and over those at rest.
    study = {(r["scene"], r["size"]): r for r in rows if r["skip"] == "on" and r["against"] == "balanced --no-skip"}
    for (scene, size), r in study.items():
        full = [v for (s, z), v in study.items() if z == size and s != "headlights"]
        if scene != "headlights" or not full:
            continue
        full_ms, key = float(full[0]["filter_ms"]), f"still.{size}"
        values[key + ".ms"], values[key + ".full_ms"] = float(r["filter_ms"]), full_ms
        values[key + ".ratio"] = float(r["filter_ms"]) / full_ms
        own = [v for v in rows if v["scene"] == scene and v["size"] == size and v["skip"] == "off"]
        if own:  # the same still scene with every stage on every frame
            values[key + ".self_ms"] = float(own[0]["filter_ms"])
        if int(r.get("rest_frames") or 0) > 0:
            values[key + ".rest_frames"], values[key + ".rest_ms"] = float(r["rest_frames"]), float(r["rest_ms"])
            values[key + ".rest_ratio"] = float(r["rest_ms"]) / full_ms
            if own:
                values[key + ".rest_self_ratio"] = float(r["rest_ms"]) / values[key + ".self_ms"]
    return rows, values


PEER_ROW = re.compile(r"^(pfstmo_pattanaik00 -t|blender fog glow) +(\S+) +(\S+) +([0-9.]+) +(\S+) +([0-9.]+) "
                      r"+([0-9.]+)x +[0-9]+x +(\S+)")


def peer_values(path="docs/bench-peers.txt"):
    values = {}
    if not os.path.exists(path):
        print(f"docs/figures.py: no {path} (docs/figures.sh --bench writes it): the peers' figures are not checked")
        return values
    for line in open(path):
        m = PEER_ROW.match(line)
        if not m:
            continue
        key = f"peers.{m[2]}.{m[3]}." + ("pattanaik" if m[1].startswith("pfstmo") else "fogglow")
        values[key + ".peer_ms"], values[key + ".eyestream_ms"] = float(m[4]), float(m[6])
        values[key + ".ratio"] = float(m[7])
        if m[5] != "-":
            values[key + ".io_ms"] = float(m[5])
        if m[8].endswith("%"):
            values[key + ".energy"] = float(m[8][:-1])
    return values


def read_map(path="docs/figures.map"):
    """Lines: FILE | sentence with {} for each number | key, key | tolerance
    (a number, a percentage, or "timing": read, rewritten, never judged)."""
    entries = []
    for n, line in enumerate(open(path), 1):
        line = line.strip()
        if not line or line.startswith("#"):
            continue
        parts = [p.strip() for p in line.split(" | ")]
        if len(parts) != 4:
            sys.exit(f"docs/figures.map:{n}: needs FILE | sentence | keys | tolerance")
        keys = [k.strip() for k in parts[2].split(",")]
        if parts[1].count("{}") != len(keys):
            sys.exit(f"docs/figures.map:{n}: {parts[1].count('{}')} numbers but {len(keys)} keys")
        entries.append((n, parts[0], parts[1], keys, parts[3]))
    return entries


def sentence_regex(sentence):
    """The sentence as a regular expression: each {} a number, and any run
    of whitespace any run (the docs break lines anywhere)."""
    out, chunks = "", sentence.split("{}")
    for i, chunk in enumerate(chunks):
        if i:
            out += NUMBER
        words = chunk.split()
        if not words:
            out += r"\s+" if chunk else ""
            continue
        lead = r"\s+" if i and chunk[0].isspace() else ""
        trail = r"\s+" if i + 1 < len(chunks) and chunk[-1].isspace() else ""
        out += lead + r"\s+".join(re.escape(w) for w in words) + trail
    return re.compile(out)


def within(quoted, value, tolerance):
    if tolerance == "timing":
        return True
    decimals = len(quoted.split(".")[1]) if "." in quoted else 0
    rounding = 0.5 * 10 ** -decimals
    allowed = float(tolerance[:-1]) / 100 * abs(value) if tolerance.endswith("%") else float(tolerance)
    return abs(float(quoted) - value) <= rounding + allowed + 1e-12


def formatted(quoted, value):
    decimals = len(quoted.split(".")[1]) if "." in quoted else 0
    return f"{value:.{decimals}f}"


BENCH_COLUMNS = ["filter_ms", "fps", "glare_ms", "adaptation_ms", "retina_ms", "mesopic_ms", "afterimage_ms",
                 "encode_ms", "setup_s", "memory_mib", "de2000_p99", "de2000_max", "state_error"]
BENCH_TABLE = re.compile(r"```\nscene +size +preset.*?\n(.*?)```", re.S)


def bench_line(row):
    """A row as `eyestream bench` prints it (pipeline/bench/bench_command.cpp)."""
    f = {c: float(row[c]) for c in BENCH_COLUMNS[:10]}
    err = row["against"] != "" and row["against"] != "-" and row["de2000_p99"] != ""
    e = (f"{float(row['de2000_p99']):.2f}", f"{float(row['de2000_max']):.2f}", f"{float(row['state_error']):.5f}",
         row["against"]) if err else ("-", "-", "-", "-")
    return (f"{row['scene']:<11} {row['size']:<6} {row['preset']:<9} {row['skip']:<4} {f['filter_ms']:9.1f} "
            f"{f['fps']:7.2f} {f['glare_ms']:7.1f} {f['adaptation_ms']:7.1f} {f['retina_ms']:7.1f} "
            f"{f['mesopic_ms']:7.1f} {f['afterimage_ms']:7.1f} {f['encode_ms']:7.1f} {f['setup_s']:7.2f} "
            f"{f['memory_mib']:7.0f} {e[0]:>6} {e[1]:>6} {e[2]:>8}  {e[3]}")


def rewrite_bench_table(rows, text):
    """performance.md's table made again from the CSV."""
    table = BENCH_TABLE.search(text)
    if not table:
        return text
    body = "\n".join(bench_line(r) for r in rows) + "\n"
    return text[:table.start(1)] + body + text[table.end(1):]


def check_bench_table(rows, failures):
    """The table in performance.md is `eyestream bench`'s output: each row
    matches the committed CSV's row in order, within its printed rounding."""
    text = open("docs/performance.md").read()
    table = BENCH_TABLE.search(text)
    if not table:
        failures.append("docs/performance.md: the bench's table is gone")
        return
    lines = [l.split() for l in table.group(1).strip().splitlines()]
    columns = BENCH_COLUMNS
    if len(lines) != len(rows):
        failures.append(f"docs/performance.md: the bench table has {len(lines)} rows, docs/bench.csv {len(rows)}")
        return
    for line, row in zip(lines, rows):
        if line[:4] != [row["scene"], row["size"], row["preset"], row["skip"]]:
            failures.append(f"docs/performance.md: bench row {' '.join(line[:4])} is not docs/bench.csv's "
                            f"{row['scene']} {row['size']} {row['preset']} {row['skip']}")
            continue
        if len(line) < 4 + len(columns):
            failures.append(f"docs/performance.md: bench row {' '.join(line[:4])} has {len(line) - 4} of "
                            f"{len(columns)} figures")
            continue
        for quoted, column in zip(line[4:4 + len(columns)], columns):
            if quoted == "-" and row["against"] in ("", "-") and column.startswith(("de2000", "state")):
                continue  # (no error measured for this row)
            if quoted == "-" or not within(quoted, float(row[column]), "0"):
                failures.append(f"docs/performance.md: bench row {' '.join(line[:4])}: {column} {quoted}, "
                                f"docs/bench.csv {row[column]}")


def main():
    if len(sys.argv) != 3 or sys.argv[1] not in ("check", "update"):
        sys.exit(__doc__)
    values = {}
    for n, line in enumerate(open(sys.argv[2]), 1):
        if line.strip():
            parts = line.split()
            if len(parts) != 2:
                sys.exit(f"docs/figures.py: {sys.argv[2]}:{n}: a command printed no value for {parts[0]}")
            values[parts[0]] = float(parts[1].rstrip(","))
    rows, bench = bench_values()
    values.update(bench)
    values.update(peer_values())
    failures, checked, texts = [], 0, {}
    for n, path, sentence, keys, tolerance in read_map():
        text = texts.setdefault(path, open(path).read())
        regex = sentence_regex(sentence)
        matches = list(regex.finditer(text))
        if not matches:
            failures.append(f"{path}: the sentence of docs/figures.map:{n} is gone: {sentence}")
            continue
        missing = [k for k in keys if k not in values]
        if missing and tolerance != "timing":  # timings are measured only with --bench
            failures.append(f"docs/figures.map:{n}: no value {', '.join(missing)} from docs/figures.sh")
        if missing:
            continue
        for m in reversed(matches):  # from the end, so rewriting keeps earlier offsets
            for i in reversed(range(len(keys))):
                quoted, value = m.group(i + 1), values[keys[i]]
                checked += 1
                if sys.argv[1] == "update":
                    text = text[:m.start(i + 1)] + formatted(quoted, value) + text[m.end(i + 1):]
                elif not within(quoted, value, tolerance):
                    failures.append(f"{path}: {keys[i]} quoted as {quoted}, printed {value:g} "
                                    f"(tolerance {tolerance}; docs/figures.map:{n})")
        texts[path] = text
    if sys.argv[1] == "update" and os.environ.get("FIGURES_BENCH") == "yes":  # a new docs/bench.csv
        texts["docs/performance.md"] = rewrite_bench_table(
            rows, texts.get("docs/performance.md") or open("docs/performance.md").read())
    if sys.argv[1] == "update":
        for path, text in texts.items():
            open(path, "w").write(text)
        print(f"docs/figures.py: {checked} quoted figures rewritten")
    else:
        check_bench_table(rows, failures)
    for f in failures:
        print("docs/figures.py: " + f)
    if failures:
        sys.exit(1)
    if sys.argv[1] == "check":
        print(f"docs/figures.py: {checked} quoted figures and the bench table match what their commands printed")


if __name__ == "__main__":
    main()
