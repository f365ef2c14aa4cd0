#!/usr/bin/python3
# One-step velocity error of "predict no change" (x_{t+1} = x_t) on prepared SMA limb data sets,
# pooled over both axes, split as in `tendril model eval --baselines`: within 3 readings of a
# throttle change (u_k != u_{k-1} for k = t, t-1 or t-2) and under steady throttle. The points are
# those a window-100 model is measured on: t has 99 rows before it and t+1 after it in its segment.
#   python3 docs/results/learned_dynamics/velocity_persistence.py [--split test|all] \
#       [--label NAME=FILE ...] [-o OUT.csv]
# Also the RMS of the filtered rate itself (what predicting zero velocity scores), in deg/s, and
# how much of the squared error the largest 1 % of the points carry (and the RMSE without them):
# a few sudden jumps of the limb, not an error spread over the data, if that share is large; and
# the share of readings with a filtered rate beyond the thesis' +-80 deg/s state bound (§5.1), and
# how many raw readings (the data set the prepared file names) moved more than 30 deg since the
# reading before (over 400 deg/s at 55-75 ms), in the same split.
import argparse, csv, math, os, sys

WINDOW, READINGS = 100, 3


def load(path):
    rows = [l for l in open(path) if not l.startswith('#')]
    return list(csv.DictReader(rows))


def jumps(path, split, times):
    raw = None
    for line in open(path):
        if line.startswith('# data_set: '):
            raw = line[len('# data_set: '):].strip()
    q = load(raw)
    th = [(x['time_s'], float(x['theta_x_deg']), float(x['theta_y_deg'])) for x in q]
    return sum(1 for k in range(1, len(th)) if th[k][0] in times and
               math.hypot(th[k][1] - th[k - 1][1], th[k][2] - th[k - 1][2]) > 30.0)


def measure(path, split):
    r = load(path)
    om = [(float(x['omega_x']), float(x['omega_y'])) for x in r]
    u = [(x['u_x'], x['u_y']) for x in r]
    seg = [(x['segment'], x['split']) for x in r]
    sums = {'all': [0.0, 0], 'change': [0.0, 0], 'steady': [0.0, 0]}
    errors = []
    rate = [0.0, 0]
    fast = 0
    run = 0  # rows of the current segment up to and including t
    for t in range(len(r)):
        run = run + 1 if t > 0 and seg[t] == seg[t - 1] else 1
        if split != 'all' and seg[t][1] != split:
            continue
        rate[0] += om[t][0] ** 2 + om[t][1] ** 2
        rate[1] += 2
        fast += max(abs(om[t][0]), abs(om[t][1])) > 80.0
        if run < WINDOW or t + 1 >= len(r) or seg[t + 1] != seg[t]:
            continue
        e = (om[t + 1][0] - om[t][0]) ** 2 + (om[t + 1][1] - om[t][1]) ** 2
        errors.append(e)
        changed = any(u[k] != u[k - 1] for k in range(t, t - READINGS, -1) if k >= 1)
        for key in ('all', 'change' if changed else 'steady'):
            sums[key][0] += e
            sums[key][1] += 1
    rmse = {k: math.sqrt(s / (2 * n)) if n else float('nan') for k, (s, n) in sums.items()}
    errors.sort()
    top = len(errors) // 100
    rest = errors[:len(errors) - top]
    rmse['share'] = sum(errors[len(errors) - top:]) / sum(errors)
    rmse['rest'] = math.sqrt(sum(rest) / (2 * len(rest)))
    rmse['fast'] = fast / (rate[1] // 2)
    rmse['jumps'] = jumps(path, split, {x['time_s'] for x in r if split == 'all' or x['split'] == split})
    return rmse, {k: n for k, (s, n) in sums.items()}, math.sqrt(rate[0] / rate[1])


def main():
    p = argparse.ArgumentParser()
    p.add_argument('--split', default='test', choices=['train', 'test', 'all'])
    p.add_argument('--label', action='append', default=[], help='NAME=FILE (prepared CSV)')
    p.add_argument('-o', '--output')
    a = p.parse_args()
    labels = a.label or ['stiff_exploration=data/sma_limb/stiff_exploration_prepared.csv']
    out = []
    for item in labels:
        name, path = item.split('=', 1)
        rmse, n, rms = measure(path, a.split)
        out.append([name, path, a.split, n['all'], n['change'], n['steady'],
                    '%.2f' % rmse['all'], '%.2f' % rmse['change'], '%.2f' % rmse['steady'],
                    '%.2f' % rms, '%.3f' % rmse['share'], '%.2f' % rmse['rest'],
                    '%.3f' % rmse['fast'], rmse['jumps']])
    head = ['data_set', 'file', 'split', 'points', 'points_input_change', 'points_steady_input',
            'persistence_rmse_omega', 'persistence_rmse_omega_input_change',
            'persistence_rmse_omega_steady_input', 'rms_omega', 'largest_1pct_share',
            'persistence_rmse_omega_without_largest_1pct', 'share_rate_beyond_80',
            'raw_jumps_over_30deg']
    if a.output:
        if os.path.exists(a.output):
            sys.exit(a.output + ': exists; nothing is overwritten')
        with open(a.output, 'w', newline='') as f:
            f.write('# one-step velocity RMSE (deg/s, both axes pooled) of predicting no change;\n'
                    '# written by docs/results/learned_dynamics/velocity_persistence.py\n')
            w = csv.writer(f, lineterminator='\n')
            w.writerow(head)
            w.writerows(out)
    print(' | '.join(head))
    for row in out:
        print(' | '.join(str(x) for x in row))


main()
