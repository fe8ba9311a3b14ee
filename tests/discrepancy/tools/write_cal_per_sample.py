"""Prints write_cal_per_sample.sh's comparison: physical coefficients (deg/h per unit^k) of the
--write-cal YAML and of the per-sample refit, their difference against the seed-to-seed SD, and
the confirmation run's 100 s stability through fog-evaluate. argv: DIR EFFECT SEED..."""
import json, statistics as st, sys
import yaml

d, eff, seeds = sys.argv[1], sys.argv[2], sys.argv[3:]

def phys(path):
    m = yaml.safe_load(open(path))['axes'][0]['bias']['model']
    sig = {s['name']: s['scale'] for s in m['signals']}
    out = {}
    for t in m['terms']:
        if t['name'] == '1':
            out['1'] = t['coef_dph']
            continue
        s, k = t['name'].rsplit('^', 1)
        out[t['name']] = t['coef_dph'] / sig[s] ** int(k)
    return out

rows = {}
for s in seeds:
    a, b = phys(f"{d}/aug_{eff}_{s}.yaml"), phys(f"{d}/ps_{eff}_{s}.yaml")
    for n in a:
        if n in b:
            rows.setdefault(n, []).append((a[n], b[n]))
print(f"{eff}, seeds {' '.join(seeds)}: --write-cal (block means) vs per-sample refit, same terms and window")
print(f"{'term':18s} {'write-cal':>11s} {'per-sample':>11s} {'diff':>11s} {'seed SD':>10s} {'diff/SD':>8s}")
for n, v in rows.items():
    blk, smp = [x[0] for x in v], [x[1] for x in v]
    sd = st.stdev(smp) if len(smp) > 1 else float('nan')
    diff = st.mean(x - y for x, y in v)
    print(f"{n:18s} {st.mean(blk):11.5g} {st.mean(smp):11.5g} {diff:11.4g} {sd:10.3g} {diff / sd if sd > 0 else float('nan'):8.2f}")
for s in seeds:
    w = json.load(open(f"{d}/d_{eff}_{s}.json"))['write_cal']['confirm_through_compensator']
    ev = {c: json.load(open(f"{d}/ev_{c}_{eff}_{s}.json"))['compensated']['stability_dph'] for c in ('base', 'ps', 'aug')}
    print(f"seed {s}: report {w['before']['stability_dph']:.5f} -> {w['after']['stability_dph']:.5f}; fog-evaluate base "
          f"{ev['base']:.5f} -> written YAML {ev['aug']:.5f} (shrink {1 - ev['aug'] / ev['base']:.3f}), per-sample refit "
          f"{ev['ps']:.5f} (shrink {1 - ev['ps'] / ev['base']:.3f})")
