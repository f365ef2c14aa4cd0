#!/usr/bin/python3
# Angle RMSE (deg, both axes pooled, step by step) of each model's open-loop rollout against the
# stiff twin's response to the same inputs: python3 docs/results/learned_dynamics/open_loop_rmse.py
import csv, math
d = 'docs/results/learned_dynamics/open_loop_'
def load(p):
    rows = [l for l in open(p) if not l.startswith('#')]
    return list(csv.DictReader(rows))
for inp in ['sine', 'square', 'sawtooth']:
    t = load(d + 'twin/open_loop_%s.csv' % inp)
    out = [inp]
    for a in ['rnn', 'lstm', 'seq2seq', 'seq2seq_attention']:
        m = load(d + '%s/open_loop_%s.csv' % (a, inp))
        n = min(len(t), len(m))
        se = [(float(m[k][c]) - float(t[k][c])) ** 2 for k in range(n) for c in ('theta_x', 'theta_y')]
        out.append('%s %.1f' % (a, math.sqrt(sum(se) / len(se))))
    print(' | '.join(out))
