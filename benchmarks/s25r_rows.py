"""Helper s25r: the rows of audit JSONs (one class) side by side, marking rows lost and gained.

    python benchmarks/s25r_rows.py CLASS BASE.json NEW.json
"""
import json
import sys


def rows(path, cls):
    d = json.load(open(path))
    return {(r["case"], r.get("variant"), r.get("set"), r["seed"]): r for r in d["rows"] if "seed" in r and r.get("case") == cls}


def main():
    cls, a, b = sys.argv[1:4]
    ra, rb = rows(a, cls), rows(b, cls)
    pa = pb = 0
    for k in sorted(set(ra) | set(rb), key=str):
        x, y = ra.get(k), rb.get(k)
        fx = "-" if x is None else ("pass" if x["faithful"] else "FAIL " + str(x["failures"]))
        fy = "-" if y is None else ("pass" if y["faithful"] else "FAIL " + str(y["failures"]))
        pa += bool(x and x["faithful"]); pb += bool(y and y["faithful"])
        mark = "  LOST" if x and y and x["faithful"] and not y["faithful"] else ("  GAINED" if x and y and y["faithful"] and not x["faithful"] else "")
        print(f"{k}: {fx} -> {fy}{mark}")
    print(f"{cls}: {pa}/{len(ra)} -> {pb}/{len(rb)}")


if __name__ == "__main__":
    main()
