#!/usr/bin/python3
"""How often two reruns of the wave-fronts study give the same simplest-model verdict, for the
verdict rule that judged each seed's period and the rule that judges the pooled time share
(docs/studies.md, "Verdict stability").

usage: verdict_reproducibility.py [--trials K] [--seed S]

A Monte Carlo of one candidate against the full particle model, judged on the front speed
alone. Each seed's front speed is drawn from a normal law: the full model's around 1.72 m/s
with a seed-to-seed spread of 0.23 m/s, the candidate's around 1.72 + Delta with 0.105 m/s
(the wet layer's front errors over 7 seeds in the main study, 0.087 and 0.040 m/s, times
sqrt(7)). Seeds are run 3 first, then 2 more at a time up to a cap, as the study does.

  before: reproduces if |difference| <= 2 combined sigma; decided when 90 % of 200 bootstrap
          resamples of the seeds give the verdict of all seeds; otherwise more seeds;
  after:  reproduces when the 95 % interval of the difference lies within 15 % of the full
          model's speed, does not when it lies wholly outside; otherwise more seeds;
  shown:  as after, but a candidate still open at the cap has not been shown to reproduce
          (the conclusion of an equivalence test that cannot reject non-equivalence), so the
          headline is "no" with the candidate marked open.

Prints, per cap and Delta, the shares of final verdicts (yes, no, undecided at the cap), the
share of reruns that give the right one (yes when Delta is within 15 % of the full model's
speed, 0.258 m/s, else no), and the probability that two independent reruns (another seed
set, or another build: round-off parts the trajectories within a few cycles) give the same
verdict, the sum of the squared shares.
"""
import argparse

import numpy as np

MEAN, SPREAD_REF, SPREAD_CAND = 1.72, 0.23, 0.105
TOLERANCE = 0.15
Z95 = 1.959963984540054


def difference(ref, cand):
    n = len(ref)
    err = np.hypot(ref.std(ddof=1), cand.std(ddof=1)) / np.sqrt(n)
    return cand.mean() - ref.mean(), err


def before(ref, cand, rng, resamples=200):
    def verdict(r, c):
        d, s = difference(r, c)
        return abs(d) <= 2 * s
    v = verdict(ref, cand)
    n = len(ref)
    same = 0
    for _ in range(resamples):
        pick = rng.integers(0, n, n)
        if len(set(pick)) < 2:  # one distinct seed: no spread, the verdict of all seeds
            same += 1
            continue
        same += verdict(ref[pick], cand[pick]) == v
    return ("yes" if v else "no"), same / resamples >= 0.9


def after(ref, cand, rng):
    d, s = difference(ref, cand)
    if abs(d) + Z95 * s <= TOLERANCE * MEAN:
        return "yes", True
    if abs(d) - Z95 * s > TOLERANCE * MEAN:
        return "no", True
    return "undecided", False


def rerun(rule, delta, cap, rng, open_at_cap="undecided"):
    ref = rng.normal(MEAN, SPREAD_REF, cap)
    cand = rng.normal(MEAN + delta, SPREAD_CAND, cap)
    n = 3
    while True:
        v, decided = rule(ref[:n], cand[:n], rng)
        if decided:
            return v
        if n + 2 > cap:
            return open_at_cap
        n += 2


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--trials", type=int, default=2000)
    ap.add_argument("--seed", type=int, default=20261203)
    ap.add_argument("--rules", default="before,after,shown", help="which rules to simulate")
    a = ap.parse_args()
    # (name, rule, the verdict of a candidate still open at the cap)
    rules = [(n, r, o) for n, r, o in (("before", before, "undecided"), ("after", after, "undecided"),
                                       ("shown", after, "no")) if n in a.rules.split(",")]
    rng = np.random.default_rng(a.seed)
    print("rule,cap,delta_m_per_s,yes,no,undecided,right,same_in_two_reruns")
    for cap in (9, 15, 21):
        for delta in (0.0, 0.1, 0.22, 0.29, 0.4):
            for name, rule, open_at_cap in rules:
                trials = a.trials // 5 if name == "before" else a.trials  # bootstrap is slow
                count = {"yes": 0, "no": 0, "undecided": 0}
                for _ in range(trials):
                    count[rerun(rule, delta, cap, rng, open_at_cap)] += 1
                p = {k: c / trials for k, c in count.items()}
                same = sum(x * x for x in p.values())
                right = p["yes"] if delta <= TOLERANCE * MEAN else p["no"]
                print(f"{name},{cap},{delta},{p['yes']:.2f},{p['no']:.2f},{p['undecided']:.2f},"
                      f"{right:.2f},{same:.2f}")


if __name__ == "__main__":
    main()
