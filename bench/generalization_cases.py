#!/usr/bin/env python3
"""Summaries of `bench_generalization --cases` output (one or more files; cases are matched by
preset, device and profile, so presets run in separate processes on the same seeds pair up):
per preset the median / p90 of held-out stability over the noise floor (in-range profiles), its
median relative to the default's with a 5-95 % bootstrap over devices (400 resamples, seed 1),
the best of the bench's standard fixed presets, and the per-device oracle: for each device the
fixed preset with the least median ratio on that device's evaluation profiles (what a selection
that knew the held-out profiles would pick), its ensemble median / p90, and the per-case minimum.

    python3 bench/generalization_cases.py tuning.txt [more.txt ...]
"""
import re, sys, math, random, collections
pat = re.compile(r'^(\S+)\s+(\d+)\s+([\d.]+)Hz (\d)T (\S+)\s+(.*?)\s+ratio\s+(\S+) raw/comp\s+(\S+)')
rows = []
for fn in sys.argv[1:]:
    for line in open(fn):
        m = pat.match(line)
        if m:
            gen, seed, hz, nt, prof, preset, ratio, rc = m.groups()
            try: ratio = float(ratio)
            except: ratio = float('inf')
            rows.append((gen, int(seed), float(hz), int(nt), prof, preset.strip(), ratio, float(rc)))
presets = list(dict.fromkeys(r[5] for r in rows))
R = {}  # (preset, dev, prof) -> ratio
devs = sorted(set((r[0], r[1]) for r in rows))
import collections as _c
_cnt=_c.Counter((r[0],r[1]) for r in rows if r[4]!='out_of_range')
_mx=max(_cnt.values()); devs=[d for d in devs if _cnt[d]==_mx]
for r in rows: R[(r[5], (r[0], r[1]), r[4])] = r[6] if math.isfinite(r[6]) else 1e9
profs = [p for p in dict.fromkeys(r[4] for r in rows) if p != 'out_of_range']
def q(v, p):
    v = sorted(v); pos = p * (len(v) - 1); lo = int(math.floor(pos)); hi = min(lo + 1, len(v) - 1)
    return v[lo] + (pos - lo) * (v[hi] - v[lo])
def cases(p, ds=None):
    return [R[(p, d, pr)] for d in (ds or devs) for pr in profs if (p, d, pr) in R]
default = 'default (multipoint)'
std_fixed = ['multipoint none 5/3', 'multipoint@3/1 none', 'multipoint@1/1 none', 'M2@3/1 none', 'M1@3/0 none']
fixed = [p for p in presets if p.endswith(' none')]
random.seed(1)
boots = [[random.choice(devs) for _ in devs] for _ in range(400)]
print(f"{len(devs)} devices, profiles {profs}")
print(f"{'preset':28s} {'median':>7s} {'p90':>7s} {'vs default med':>15s} {'boot 5-95%':>15s}  paired med log")
bm = lambda p, ds: q(cases(p, ds), 0.5)
for p in presets:
    c = cases(p)
    if not c: continue
    rel = bm(p, devs) / bm(default, devs) - 1
    bs = sorted(bm(p, b) / bm(default, b) - 1 for b in boots)
    pl = [math.log(R[(p, d, pr)] / R[(default, d, pr)]) for d in devs for pr in profs if (p, d, pr) in R and (default, d, pr) in R]
    print(f"{p:28s} {q(c,.5):7.2f} {q(c,.9):7.2f} {100*rel:+14.1f}% {100*q(bs,.05):+6.1f}..{100*q(bs,.95):+5.1f}%  {q(pl,.5):+.3f}")
sf = [p for p in std_fixed if p in presets]
if sf:
    best = min(sf, key=lambda p: bm(p, devs))
    print(f"best standard fixed preset: {best} {bm(best, devs):.2f}")
# oracle: per device, the fixed preset with the least median ratio over its in-range profiles
for label, pool in (('standard fixed', sf), ('all fixed', fixed)):
    if not pool: continue
    orc, picks = [], []
    for d in devs:
        b = min(pool, key=lambda p: q([R[(p, d, pr)] for pr in profs], 0.5))
        picks.append((d[1], b)); orc += [R[(b, d, pr)] for pr in profs]
    percase = [min(R[(p, d, pr)] for p in pool) for d in devs for pr in profs]
    print(f"oracle per device ({label}): median {q(orc,.5):.2f} p90 {q(orc,.9):.2f}; per case: median {q(percase,.5):.2f} p90 {q(percase,.9):.2f}")
if True:
    print("per device medians:")
    show = [default] + [p for p in presets if p != default]
    print('seed ' + ' '.join(f"{p[:10]:>10s}" for p in show))
    for d in devs:
        print(f"{d[1]:4d} " + ' '.join(f"{q([R[(p,d,pr)] for pr in profs if (p,d,pr) in R],.5) if any((p,d,pr) in R for pr in profs) else float('nan'):10.2f}" for p in show))
