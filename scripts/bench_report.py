#!/usr/bin/env python3
"""Every table and figure of docs/benchmarks.md from eaci_bench's records.

Usage: scripts/bench_report.py [--records DIR] [--doc FILE] [--figures DIR] [--stdout] [STUDY ...]

STUDY is paper, sweep, front, scale, deadline, costs or scen (default: every DIR/STUDY.jsonl there is).
For each, the Markdown between `<!-- generated: STUDY -->` (and `sweep-aco`) and `<!-- end -->` in the doc is
replaced by the tables made from DIR/STUDY.jsonl (--stdout: printed instead), and the study's
figures are drawn into the figures directory. A record is one JSON line written by eaci_bench
(src/bench/record.hpp): command, map, variant, seed, problem, parameters (those that differ from
the defaults), run (the plan's numbers), extra (the study's own measures), provenance.
Needs Debian's python3-pandas and python3-matplotlib (run with /usr/bin/python3).
"""

import argparse
import json
import math
import os
import re

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402
from matplotlib.colors import ListedColormap, LogNorm  # noqa: E402

INF = math.inf
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
STUDIES = ["paper", "sweep", "front", "scale", "deadline", "costs", "scen"]
PAPER_LABEL = {"astar": "A*", "aco": "classic ACO", "aco-strong": "classic ACO, τ0 = 1, ρ = 0.3",
               "eaci-paper": "EACI, paper islands", "eaci-geodesic": "EACI, geodesic islands",
               "maaco": "MAACO (re-implemented from public descriptions, not the authors' code)"}
PAPER_COLOR = {"astar": "0.45", "aco": "tab:red", "aco-strong": "tab:orange", "eaci-paper": "tab:blue",
               "eaci-geodesic": "tab:green", "maaco": "tab:purple"}
MAACO_ALT = "maaco-alt "  # the variants that change one of MAACO's open choices (docs/algorithm.md)
# The baselines the paper compares with whose rules are not public: their rows are quoted, not run.
NOT_RUN_REASON = "not run here: its rules are not public, docs/algorithm.md"
SYMBOL = {"epsilon": "ε", "lambda": "λ", "islands": "N", "kappa": "κ"}
FIGURE = {"epsilon": "Fig. 11", "lambda": "Fig. 12", "islands": "Fig. 13", "kappa": "Fig. 14"}
COST_LABEL = {"astar": "A*", "astar-smoothed": "A*, smoothed", "eaci": "EACI", "eaci-smoothed": "EACI, smoothed"}
SCALE_LABEL = {"astar": "A*", "eaci-1t": "EACI 1 thread", "eaci-all": "EACI all cores",
               "eaci-early-1t": "EACI early stop, 1 thread", "eaci-early-all": "EACI early stop, all cores",
               "aco-1t": "ACO 1 thread", "aco-all": "ACO all cores"}


# ---------------------------------------------------------------- records and numbers

def num(v):
    """A record's number; JSON null (a non-finite number) as +infinity."""
    return INF if v is None or (isinstance(v, float) and math.isnan(v)) else v


def load(path):
    with open(path) as f:
        rows = [json.loads(line) for line in f if line.strip()]
    kept = {key: [r.pop(key) for r in rows] for key in ("provenance", "parameters")}
    df = pd.json_normalize(rows, max_level=1)
    for key, values in kept.items():
        df[key] = values
    df["length"] = [num(x) if ok else INF for x, ok in zip(df["run.length"], df["run.success"])]
    return df


def mean(xs):
    xs = list(xs)
    return sum(xs) / len(xs) if xs else INF  # summed in order, as the C++ harness did


def median(xs):
    xs, n = sorted(xs), len(xs)
    return INF if n == 0 else xs[n // 2] if n % 2 else 0.5 * (xs[n // 2 - 1] + xs[n // 2])


def std(xs):
    m = mean(xs)
    return math.sqrt(sum((x - m) * (x - m) for x in xs) / (len(xs) - 1)) if len(xs) > 1 else 0.0


def fixed(v, d):
    if v is None or not math.isfinite(v):
        return "—"
    if abs(v) < 0.5 * 10 ** -d:
        v = 0.0
    return f"{v:.{d}f}"


def ratio(a, b):
    return "—" if not (math.isfinite(a) and math.isfinite(b)) or b == 0 else fixed(a / b, 2) + "×"


def gap(length, optimum):
    return (length / optimum - 1) * 100 if math.isfinite(length) and math.isfinite(optimum) and optimum > 0 else INF


def ms(v):
    return fixed(v, 2 if v < 10 else 1)


def table(header, rows):
    out = ["| " + " | ".join(header) + " |", "|---|" + "---:|" * (len(header) - 1)]
    out += ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]
    return "\n".join(out) + "\n"


def provenance(df):
    p = df["provenance"].iloc[0]
    source = f"Source `{p['git_commit']}`"
    if p["modified_solver_sources"]:
        source += " with uncommitted changes to" + "".join(f" `{f}`" for f in p["modified_solver_sources"])
    elif p["git_dirty"]:
        source += " with uncommitted changes outside the solver sources"
    command = re.sub(r"--out \S+", "--out out/bench", re.sub(r"^\S*eaci_bench\S*", "build/bench/bin/eaci_bench", p["command_line"]))
    return (f"{source}; {p['compiler']}, {p['build_type']}; {p['cpu_model']}, {p['hardware_threads']} hardware "
            f"threads, {round(p['memory_gb'])} GB; {p['date_utc']}; load average {p['load_average_at_start']:g} "
            f"when the run began.\n\nCommand: `{command}`\n")


def summary(runs, optimum=INF):
    """The paper tables' columns over one planner's runs (a DataFrame slice)."""
    lengths = [x for x in runs["length"] if math.isfinite(x)]
    s = {"runs": len(runs), "successes": len(lengths),
         "optimal": sum(1 for x in lengths if abs(x - optimum) < 1e-6),
         "avg_length": mean(lengths), "best_length": min(lengths, default=INF), "std": std(lengths),
         "iterations": mean(runs["run.iterations_to_converge"]), "lost": mean(runs["run.lost_ants_total"]),
         "time": median(runs["run.time_ms"]), "cpu": median(runs["run.cpu_ms"]),
         "to_best": median(runs["run.time_to_best_ms"])}
    best = 0  # the shortest route; among equally short ones the least turning, then the first
    ls, turns = list(runs["length"]), list(runs["run.total_turn_deg"])
    for k in range(1, len(ls)):
        if ls[k] < ls[best] - 1e-6 or (abs(ls[k] - ls[best]) <= 1e-6 and turns[k] < turns[best]):
            best = k
    s["best_index"], s["turn"] = best, turns[best] if turns else 0.0
    order = sorted(range(len(ls)), key=lambda k: (ls[k], runs["run.iterations_to_converge"].iloc[k],
                                                  runs["run.lost_ants_total"].iloc[k]))
    s["median_index"] = order[(len(order) - 1) // 2] if order else 0
    s["gap"] = gap(s["avg_length"], optimum)
    return s


def paper_maps():
    with open(os.path.join(ROOT, "maps", "paper", "paper_maps.json")) as f:
        return {m["name"]: m for m in json.load(f)["maps"]}


def grid_of(name):
    """A paper map's obstacles (True) from maps/paper."""
    return np.loadtxt(os.path.join(ROOT, "maps", "paper", name + ".txt"), dtype=int).astype(bool)


# ---------------------------------------------------------------- paper

def family_of(variant):
    return "ACO" if variant.startswith("aco") else "MAACO" if variant.startswith("maaco") else "EACI"


def paper_row(label, b):
    return [label, fixed(b[0], 2), fixed(b[1], 2), fixed(b[2], 2), fixed(b[3], 4), fixed(b[4], 2), fixed(b[5], 0),
            "", "", "", "", ""]


def paper_tables(df):
    specs = paper_maps()
    out = [provenance(df)]
    alternatives = df[df["variant"].str.startswith(MAACO_ALT)]
    df = df[~df["variant"].str.startswith(MAACO_ALT)]
    ratios, timings, maaco_ratios = [], [], []
    for name, m in df.groupby("map", sort=False):
        spec, astar = specs[name], m[m["variant"] == "astar"].iloc[0]
        optimum = astar["length"]
        w, h = astar["problem.width"], astar["problem.height"]
        title = f"#### {name} ({w}×{h}, {spec['start_serial']} → {spec['goal_serial']})"
        title += f", the paper's {spec['table']}" if spec["table"] else ""
        note = "" if spec["table"] else " The paper's rows are those of the 20×20 above."
        rows = [["A* (exact)", "", fixed(optimum, 4), fixed(optimum, 4), "", "", fixed(astar["run.total_turn_deg"], 0),
                 "1/1" if astar["run.success"] else "0/1", "", "0 %", fixed(astar["run.time_ms"], 3), ""]]
        sums, last_family = {}, None
        for variant, runs in m[m["variant"] != "astar"].groupby("variant", sort=False):
            s = sums[variant] = summary(runs, optimum)
            family = family_of(variant)
            baselines = spec.get("paper_baselines", {})
            row = {"ACO": spec["paper_aco"], "EACI": spec["paper_eaci"], "MAACO": baselines.get("MAACO")}[family]
            if row and family != last_family:
                if family == "EACI":  # the paper's other baselines whose rules are not public
                    for other, b in baselines.items():
                        if other != "MAACO":
                            rows.append(paper_row(f"paper: {other} ({NOT_RUN_REASON})", b))
                rows.append(paper_row(f"paper: {family}", row))
            last_family = family
            rows.append([f"ours: {PAPER_LABEL[variant]}", fixed(s["iterations"], 2), fixed(s["avg_length"], 4),
                         fixed(s["best_length"], 4), fixed(s["std"], 4), fixed(s["lost"], 2), fixed(s["turn"], 0),
                         f"{s['successes']}/{s['runs']}", f"{s['optimal']}/{s['runs']}", fixed(s["gap"], 2) + " %",
                         fixed(s["time"], 2), fixed(s["to_best"], 2)])
        out.append(f"{title}\n\nMap: {spec['source']}.{note}\n\n" + table(
            ["row", "iterations", "avg length", "best length", "std", "lost ants", "angle (°)", "success", "optimal",
             "gap", "ms/run", "ms to best"], rows))
        if spec["paper_aco"]:
            aco, eaci = spec["paper_aco"], spec["paper_eaci"]
            a, st, p, g = sums["aco"], sums["aco-strong"], sums["eaci-paper"], sums["eaci-geodesic"]
            ratios.append([name, ratio(a["iterations"], aco[0]), ratio(a["lost"], aco[4]),
                           ratio(st["iterations"], aco[0]), ratio(st["lost"], aco[4]),
                           ratio(p["iterations"], eaci[0]), ratio(p["lost"], eaci[4]),
                           ratio(p["best_length"], eaci[2]), ratio(p["turn"], eaci[5]),
                           f"{g['optimal']}/{g['runs']}", ratio(g["iterations"], eaci[0]), ratio(g["lost"], eaci[4])])
        if "maaco" in sums and spec.get("paper_baselines", {}).get("MAACO"):
            b, mm = spec["paper_baselines"]["MAACO"], sums["maaco"]
            maaco_ratios.append([name, ratio(mm["iterations"], b[0]), ratio(mm["avg_length"], b[1]),
                                 ratio(mm["best_length"], b[2]), ratio(mm["std"], b[3]), ratio(mm["lost"], b[4]),
                                 ratio(mm["turn"], b[5])])
        g = sums["eaci-geodesic"]["to_best"]
        timings.append([name, "A*", fixed(astar["run.time_ms"], 3), fixed(astar["run.cpu_ms"], 3),
                        fixed(astar["run.time_ms"], 3), ratio(astar["run.time_ms"], g)])
        timings += [["", PAPER_LABEL[v], fixed(s["time"], 2), fixed(s["cpu"], 2), fixed(s["to_best"], 2),
                     ratio(s["to_best"], g)] for v, s in sums.items()]
    out.append("#### Ours ÷ paper\n\nRatios of our averages to the paper's EACI and ACO rows (1.00× = equal; "
               "*optimal*: runs that returned the A* optimum).\n\n" + table(
                   ["map", "ACO iterations", "ACO lost ants", "ACO τ0 1 ρ 0.3 iterations", "ACO τ0 1 ρ 0.3 lost ants",
                    "EACI-paper iterations", "EACI-paper lost ants", "EACI-paper best length", "EACI-paper angle",
                    "EACI-geodesic optimal", "EACI-geodesic iterations", "EACI-geodesic lost ants"], ratios))
    if maaco_ratios:
        out.append(f"#### {PAPER_LABEL['maaco']} ÷ the paper's MAACO\n\n" + table(
            ["map", "iterations", "avg length", "best length", "std", "lost ants", "angle"], maaco_ratios))
    if not alternatives.empty:
        out.append(maaco_choice_table(df, alternatives, specs))
    threads = df["parameters"].iloc[0].get("threads", 1)
    out.append(f"#### Time to the final route\n\nMedians over the runs (robust to other load on the machine) of one "
               f"`eaci::plan()` call on {threads} thread(s): wall time, CPU time of the process (hardly affected by "
               f"other programs on the cores), and wall time until the end of the iteration that found the run's final "
               f"route.\n\n" + table(["map", "planner", "wall ms/run", "CPU ms/run", "wall ms to final route",
                                      "to final route ÷ EACI-geodesic's"], timings))
    return "\n".join(out)


def maaco_choice_table(df, alternatives, specs):
    """MAACO with this project's decisions, then with one open choice changed at a time."""
    rows = []
    for name, m in df.groupby("map", sort=False):
        if "maaco" not in set(m["variant"]):
            continue
        optimum = m[m["variant"] == "astar"].iloc[0]["length"]
        b = specs[name].get("paper_baselines", {}).get("MAACO")
        if b:
            rows.append(paper_row(f"{name}: paper", b)[:7] + [""])
        for variant, runs in [("maaco", m[m["variant"] == "maaco"])] + list(
                alternatives[alternatives["map"] == name].groupby("variant", sort=False)):
            s = summary(runs, optimum)
            label = "decided" if variant == "maaco" else variant[len(MAACO_ALT):]
            rows.append([f"{name}: {label}", fixed(s["iterations"], 2), fixed(s["avg_length"], 4),
                         fixed(s["best_length"], 4), fixed(s["std"], 4), fixed(s["lost"], 2), fixed(s["turn"], 0),
                         f"{s['optimal']}/{s['runs']}"])
    return (f"#### {PAPER_LABEL['maaco']}: its open choices\n\nThe decided row, then each other public reading of "
            "one choice alone (docs/algorithm.md, MAACO).\n\n" + table(
                ["row", "iterations", "avg length", "best length", "std", "lost ants", "angle (°)", "optimal"], rows))


def draw_grid(ax, grid, cmap=ListedColormap(["white", "black"])):
    ax.imshow(grid, cmap=cmap, vmin=0, vmax=1, interpolation="nearest")
    ax.set(xticks=[], yticks=[])


def draw_route(ax, cells, color, **kw):
    if cells:
        ax.plot([c[1] for c in cells], [c[0] for c in cells], color=color, **kw)


def draw_islands(ax, islands):
    if islands and len(islands) > 2:
        ax.plot([c[1] for c in islands[1:-1]], [c[0] for c in islands[1:-1]], "D", color="magenta", ms=5, mec="black")


def save(fig, figures, name):
    fig.savefig(os.path.join(figures, name), dpi=110, bbox_inches="tight")
    plt.close(fig)


def map_panels(n, width, height):
    cols = 3 if n > 4 else 2
    fig, axes = plt.subplots(math.ceil(n / cols), cols, figsize=(width * cols, height * math.ceil(n / cols)),
                             squeeze=False)
    for ax in axes.flat[n:]:
        ax.axis("off")
    return fig, list(axes.flat)


def paper_figures(df, figures):
    df = df[~df["variant"].str.startswith(MAACO_ALT)]
    specs = paper_maps()
    maps = list(df.groupby("map", sort=False))
    for name, m in maps:
        grid, astar = grid_of(name), m[m["variant"] == "astar"].iloc[0]
        variants = list(m[m["variant"] != "astar"].groupby("variant", sort=False))
        fig, axes = plt.subplots(1, len(variants) + 1, figsize=(4.2 * (len(variants) + 1), 4.6))
        draw_grid(axes[0], grid)
        draw_route(axes[0], astar["run.path"], PAPER_COLOR["astar"], lw=2.4)
        axes[0].set_title(f"A* (optimum)\n{astar['length']:.4f}", fontsize=10)
        for ax, (variant, runs) in zip(axes[1:], variants):
            best = runs.iloc[summary(runs, astar["length"])["best_index"]]
            draw_grid(ax, grid)
            draw_route(ax, astar["run.path"], "0.6", ls="--", lw=1.2)
            draw_route(ax, best["run.path"], PAPER_COLOR[variant], lw=2.4)
            draw_islands(ax, best["run.islands"])
            ax.set_title(f"{PAPER_LABEL[variant]}\nbest {best['length']:.4f}, {best['run.total_turn_deg']:.0f}°",
                         fontsize=10)
            snapshots = runs.iloc[0]["extra.pheromone_snapshots"] if "extra.pheromone_snapshots" in runs else None
            if isinstance(snapshots, list) and snapshots:
                fig2, axes2 = plt.subplots(1, len(snapshots), figsize=(3.4 * len(snapshots), 3.6), squeeze=False)
                fields = [np.asarray(s["strongest"], dtype=float).reshape(grid.shape) for s in snapshots]
                free = np.concatenate([f[~grid] for f in fields])
                vmax = free.max()
                vmin = max(free[free > 0].min(), vmax * 1e-6)
                cmap = plt.get_cmap("viridis").copy()
                cmap.set_bad("black")
                for ax2, s, f in zip(axes2[0], snapshots, fields):
                    image = ax2.imshow(np.ma.masked_where(grid, np.clip(f, vmin, vmax)), cmap=cmap,
                                       norm=LogNorm(vmin=vmin, vmax=vmax), interpolation="nearest")
                    ax2.set_title("initial" if s["iteration"] == 0 else f"after iteration {s['iteration']}")
                    ax2.set(xticks=[], yticks=[])
                fig2.colorbar(image, ax=list(axes2[0]), shrink=0.8, label="strongest pheromone leaving the cell")
                fig2.suptitle(f"{name}: {PAPER_LABEL[variant]}, seed 1 (obstacles black)")
                save(fig2, figures, f"pheromone_{name}_{variant.replace('eaci-', '')}.png")
        fig.suptitle(f"{name}: best route of each planner (dashed: the A* optimum; diamonds: islands)")
        save(fig, figures, f"routes_{name}.png")

    for kind in ("convergence", "convergence_time", "lost_ants"):
        shown = [(n, m) for n, m in maps if kind != "convergence_time" or specs[n]["table"]]
        fig, axes = map_panels(len(shown), 5.6, 4.4)
        for ax, (name, m) in zip(axes, shown):
            optimum = m[m["variant"] == "astar"].iloc[0]["length"]
            for variant, runs in m[m["variant"] != "astar"].groupby("variant", sort=False):
                run = runs.iloc[summary(runs, optimum)["median_index"]]
                color, label = PAPER_COLOR[variant], PAPER_LABEL[variant]
                best = [num(x) for x in run["run.best_cost_so_far"]]
                if kind == "convergence":
                    ax.plot(range(1, len(best) + 1), best, color=color, lw=2, label=label)
                    ax.plot(range(1, len(best) + 1), [num(x) for x in run["run.iteration_best_cost"]], color=color,
                            lw=0.8, alpha=0.45)
                elif kind == "convergence_time":
                    ax.step(run["run.iteration_end_ms"], best, where="post", color=color, lw=2, label=label)
                    ax.set_xscale("log")
                else:
                    lost = np.array(list(runs["run.lost_ants_per_iteration"]), dtype=float).mean(axis=0)
                    ax.plot(range(1, len(lost) + 1), lost, color=color, lw=1.8, label=label)
                    ax.set_xscale("log")
            if kind != "lost_ants":
                ax.axhline(optimum, color="0.3", ls="--", lw=1, label="A* optimum")
                ax.set_ylim(optimum * 0.97, optimum * 1.5)
            ax.set(title=name, xlabel="wall time (ms, one thread)" if kind == "convergence_time" else "iteration",
                   ylabel="lost ants (of 50), mean of the runs" if kind == "lost_ants" else "route length (cells)")
            ax.grid(alpha=0.3)
        handles, labels = axes[0].get_legend_handles_labels()
        fig.legend(handles, labels, loc="lower center", ncol=len(labels), fontsize=9, frameon=False)
        fig.suptitle({"convergence": "Convergence, median run (thick: best so far; thin: best of the iteration)",
                      "convergence_time": "Best route so far against wall time (median run)",
                      "lost_ants": "Lost ants per iteration"}[kind])
        fig.tight_layout(rect=(0, 0.05, 1, 1))
        save(fig, figures, kind + ".png")


# ---------------------------------------------------------------- sweep

def sweep_points(df):
    """Per (axis, value, map, variant): the summary, against the map's A* optimum."""
    optimum = {n: g.iloc[0]["length"] for n, g in df[df["variant"] == "astar"].groupby("map")}
    runs = df[df["variant"] != "astar"]
    value = runs["extra.value"] if "extra.value" in runs else np.nan
    keys = [runs["extra.axis"], value.fillna(0), runs["extra.aco_rho"].fillna(0), runs["extra.aco_tau0"].fillna(0),
            runs["map"], runs["variant"]]
    return {k: summary(g, optimum[k[4]]) for k, g in runs.groupby(keys, sort=False)}


def sweep_tables(df):
    specs, points = paper_maps(), sweep_points(df)
    out = [provenance(df)]
    eaci = [k for k in points if k[0] != "aco"]
    for axis in dict.fromkeys(k[0] for k in eaci):
        for name in dict.fromkeys(k[4] for k in eaci):
            variants = list(dict.fromkeys(k[5] for k in eaci if k[0] == axis and k[4] == name))
            header = [SYMBOL[axis]] + [f"{v[5:]}: {c}" for v in variants
                                       for c in ("length", "iterations", "lost ants", "optimal")]
            rows = []
            for value in dict.fromkeys(k[1] for k in eaci if k[0] == axis and k[4] == name):
                row = [f"{value:g}"]
                for v in variants:
                    s = points[(axis, value, 0, 0, name, v)]
                    row += [fixed(s["avg_length"], 3), fixed(s["iterations"], 2), fixed(s["lost"], 1),
                            f"{s['optimal']}/{s['runs']}"]
                rows.append(row)
            out.append(f"#### {SYMBOL[axis]} (`{axis}`, the paper's {FIGURE[axis]}) on {name}\n\n" + table(header, rows))
    aco = {(k[3], k[2], k[4]): s for k, s in points.items() if k[0] == "aco"}
    if not aco:
        return {"sweep": "\n".join(out)}
    eaci_out, out = out, []

    def within(s, paper):
        return all(0.5 <= x <= 2 for x in (s["iterations"] / paper[0], s["lost"] / paper[4]))

    maps = list(dict.fromkeys(k[2] for k in aco))
    rhos, taus = list(dict.fromkeys(k[1] for k in aco)), list(dict.fromkeys(k[0] for k in aco))
    rows = []
    for name in maps:
        p = specs[name]["paper_aco"]
        for rho in rhos:
            s = aco[(800, rho, name)]
            rows.append([name, f"{rho:g}", fixed(s["iterations"], 2), fixed(p[0], 1), ratio(s["iterations"], p[0]),
                         fixed(s["lost"], 1), fixed(p[4], 1), ratio(s["lost"], p[4]), fixed(s["avg_length"], 3),
                         fixed(s["best_length"], 3), f"{s['successes']}/{s['runs']}", "yes" if within(s, p) else "no"])
    out.append("#### τ0 = 800 (our default; our default ρ is 0.1)\n\n" + table(
        ["map", "ρ", "iterations", "paper", "ours ÷ paper", "lost ants", "paper", "ours ÷ paper", "avg length",
         "best length", "success", "within 2× on both"], rows))
    text, passing = ["#### Every τ0: average iterations (ours ÷ paper) / average lost ants (ours ÷ paper)\n\nOnly τ0 "
                     "relative to Q / L matters (the roulette wheel of Eq. 8 does not change when every τ is scaled): "
                     "τ0 = 800 with Q = 100 equals the common MATLAB ACO code's τ0 = 8 with Q = 1.\n"], []
    for tau in taus:
        rows = []
        for rho in rhos:
            row, ok = [f"{rho:g}"], True
            for name in maps:
                s, p = aco[(tau, rho, name)], specs[name]["paper_aco"]
                ok = ok and within(s, p)
                row.append(f"{fixed(s['iterations'], 1)} ({ratio(s['iterations'], p[0])}) / {fixed(s['lost'], 0)} "
                           f"({ratio(s['lost'], p[4])})")
            rows.append(row + ["**yes**" if ok else "no"])
            if ok:
                passing.append(f"τ0 = {tau:g} with ρ = {rho:g}")
        text.append(f"τ0 = {tau:g}:\n\n" + table(
            ["ρ"] + [f"{n}: iterations / lost ants" for n in maps] + ["all maps within 2×"], rows))
    out += text
    out.append("Settings within a factor 2 on every map: " + (", ".join(passing) or "none") + "\n")
    return {"sweep": "\n".join(eaci_out), "sweep-aco": "\n".join(out)}


def sweep_figures(df, figures):
    points = sweep_points(df)
    for axis in dict.fromkeys(k[0] for k in points if k[0] != "aco"):
        fig, axes = plt.subplots(1, 3, figsize=(15, 4.2))
        keys = [k for k in points if k[0] == axis]
        for ax, (metric, label) in zip(axes, [("avg_length", "average route length"),
                                              ("iterations", "average iterations"), ("lost", "average lost ants")]):
            for i, (name, variant) in enumerate(dict.fromkeys((k[4], k[5]) for k in keys)):
                sel = [k for k in keys if k[4] == name and k[5] == variant]
                ax.plot([k[1] for k in sel], [points[k][metric] for k in sel], marker="o", ms=4,
                        color=PAPER_COLOR[variant], ls=["-", "--", ":"][i // 2 % 3], label=f"{name}, {variant}")
            if axis == "lambda":
                ax.set_xscale("log")
            if metric == "lost":
                ax.set_yscale("symlog", linthresh=1.0)
            ax.set(xlabel=f"{SYMBOL[axis]} ({axis})", ylabel=label)
            ax.grid(alpha=0.3)
        axes[0].legend(fontsize=8)
        fig.suptitle(f"EACI against {SYMBOL[axis]} (the paper's {FIGURE[axis]}); N = 6 unless swept")
        fig.tight_layout()
        save(fig, figures, f"sweep_{axis}.png")
    aco = {(k[3], k[2], k[4]): s for k, s in points.items() if k[0] == "aco"}
    if aco:
        specs, maps = paper_maps(), list(dict.fromkeys(k[2] for k in aco))
        taus = list(dict.fromkeys(k[0] for k in aco))
        fig, axes = plt.subplots(2, len(maps), figsize=(4.2 * len(maps), 7.5), squeeze=False)
        for col, name in enumerate(maps):
            for row, (metric, index, label) in enumerate([("iterations", 0, "avg iterations, ours ÷ paper"),
                                                          ("lost", 4, "avg lost ants, ours ÷ paper")]):
                ax = axes[row][col]
                ax.axhspan(0.5, 2.0, color="tab:green", alpha=0.12)
                for tau, color in zip(taus, plt.get_cmap("plasma")(np.linspace(0, 0.8, len(taus)))):
                    sel = sorted(k for k in aco if k[0] == tau and k[2] == name)
                    ax.plot([k[1] for k in sel], [aco[k][metric] / specs[name]["paper_aco"][index] for k in sel],
                            marker="o", ms=4, color=color, label=f"τ0 = {tau:g}")
                ax.set(yscale="log", xlabel="ρ (aco_rho)", ylabel=label, title=name)
                ax.grid(alpha=0.3, which="both")
        axes[0][0].legend(fontsize=8)
        fig.suptitle("Classic ACO against the paper's ACO row (green: within a factor 2)")
        fig.tight_layout()
        save(fig, figures, "aco_rho.png")


# ---------------------------------------------------------------- scale and deadline

def scale_cases(df):
    """Per map (kind and size): its seeds' maps and the runs of each planner."""
    for name, case in df.groupby("map", sort=False):
        yield name, case, {v: r for v, r in case.groupby("variant", sort=False)}


def scale_tables(df):
    out = [provenance(df)]
    times, quality, memory, early, notes = [], [], [], [], []
    for name, case, by in scale_cases(df):
        maps = case.drop_duplicates("problem.map_seed")
        row = [name, len(maps), fixed(mean(maps["problem.obstacle_fraction"]) * 100, 0) + " %",
               fixed(mean(maps["problem.optimum"]), 1)]
        for key in SCALE_LABEL:
            r = by.get(key)
            if r is None:
                row.append("—")
                continue
            t = median(r["run.time_ms"])
            cell = fixed(t, 2 if t < 10 else 0)
            if r["run.interrupted"].any():
                cell += " (capped)"
            elif len(r) < len(maps):
                cell += f" ({len(r)} run)"
            row.append(cell)
        times.append(row)
        row = [name]
        for key, lost_digits in (("eaci-1t", 1), ("aco-1t", 0)):
            r = by.get(key)
            if r is None:
                row += ["—"] * 4
                continue
            gaps = [gap(x, o) for x, o in zip(r["length"], r["problem.optimum"]) if math.isfinite(x)]
            row += [f"{len(gaps)}/{len(r)}", f"{fixed(mean(gaps), 2)} / {fixed(max(gaps), 2)}" if gaps else "—",
                    fixed(mean(r["run.iterations_to_converge"]), 1) if gaps else "—",
                    fixed(mean(r["run.lost_ants_total"]), lost_digits)]
        quality.append(row)
        memory.append([name] + [fixed(max(by[k]["extra.peak_rss_mb"]), 1) + " (" + fixed(max(by[k]["extra.plan_rss_mb"]), 1)
                                + ")" if k in by else "—" for k in SCALE_LABEL if k != "eaci-early-all"])
        if all(k in by for k in ("eaci-early-1t", "eaci-1t", "astar")):  # seeds where both EACI runs found a route
            e = by["eaci-early-1t"].merge(by["eaci-1t"], on="seed", suffixes=("", ".full")).merge(
                by["astar"], on="seed", suffixes=("", ".astar"))
            e = e[e["run.success"] & e["run.success.full"]]
            if len(e):
                f_ms, e_ms, a_ms = sum(e["run.time_ms.full"]), sum(e["run.time_ms"]), sum(e["run.time_ms.astar"])
                early.append([name, fixed(a_ms / len(e), 2), fixed(f_ms / len(e), 1), fixed(e_ms / len(e), 1),
                              fixed((1 - e_ms / f_ms) * 100, 0) + " %",
                              fixed(mean((x / y - 1) * 100 for x, y in zip(e["length"], e["length.full"])), 2) + " %",
                              fixed(mean(map(gap, e["length"], e["problem.optimum"])), 2) + " %",
                              fixed(mean(e["run.iterations_run"]), 1), ratio(e_ms, a_ms),
                              fixed(mean(e["run.first_iteration_ms"]), 1)])
        if "extra.note" in case:
            notes += [f"- {name}: {r['variant']} seed {r['seed']}: {r['extra.note']}"
                      for _, r in case.iterrows() if isinstance(r["extra.note"], str)]
    out.append("#### Time per plan (ms of wall time, median over the seeds)\n\n" + table(
        ["map", "seeds", "obstacles", "A* length"] + list(SCALE_LABEL.values()), times))
    out.append("#### Route quality (one thread)\n\n*gap*: route length over the A* optimum of the same map, average "
               "and worst over the successful runs; *iterations*: iterations to converge.\n\n" + table(
                   ["map", "EACI success", "EACI gap avg / max %", "EACI iterations", "EACI lost ants", "ACO success",
                    "ACO gap avg / max %", "ACO iterations", "ACO lost ants"], quality))
    out.append("#### Peak memory per plan (MiB)\n\nThe child process's peak resident set (`ru_maxrss` from `wait4`), "
               "worst over the seeds; in brackets what the plan added to the child's resident set at its start.\n\n"
               + table(["map"] + [v for k, v in SCALE_LABEL.items() if k != "eaci-early-all"], memory))
    out.append("#### EACI with early stopping\n\nOne thread; wall times are means over the seeds; *length cost*: "
               "early-stopped route over the full run's route, same seed; *set-up + 1st iteration*: wall time until "
               "the first iteration ended.\n\n" + table(
                   ["map", "A* ms", "EACI full ms", "EACI early-stop ms", "time saved", "length cost",
                    "early-stop gap to A*", "iterations run", "early stop ÷ A*", "set-up + 1st iteration ms"], early))
    if notes:
        out.append("#### Notes\n\n" + "\n".join(notes) + "\n")
    return "\n".join(out)


def scale_value(metric, r):
    """One point of a scale figure: the runs `r` of one planner on one map size."""
    if metric == "success":
        return 100 * mean(map(math.isfinite, r["length"]))
    if metric == "gap":
        gaps = [gap(x, o) for x, o in zip(r["length"], r["problem.optimum"]) if math.isfinite(x)]
        return mean(gaps) if gaps else math.nan
    return (median if metric == "run.time_ms" else max)(list(r[metric]))


def scale_figures(df, figures):
    for metric, ylabel, name in (("run.time_ms", "wall time per plan (ms, median)", "scale_time"),
                                 ("extra.peak_rss_mb", "peak resident set (MiB, worst)", "scale_memory"),
                                 ("gap", "length over A* (%, mean of the successful runs)", "scale_gap"),
                                 ("success", "runs that found a route (%)", "scale_success")):
        kinds = list(dict.fromkeys(df["problem.kind"]))
        fig, axes = plt.subplots(1, len(kinds), figsize=(6.5 * len(kinds), 4.6), squeeze=False)
        for ax, kind in zip(axes[0], kinds):
            sel = df[df["problem.kind"] == kind]
            for key, label in SCALE_LABEL.items():
                if metric == "gap" and key == "astar":
                    continue
                cases = sel[sel["variant"] == key].groupby("problem.size")
                ax.plot([size for size, _ in cases], [scale_value(metric, r) for _, r in cases], marker="o", label=label)
            ax.set(xscale="log", yscale={"gap": "symlog", "success": "linear"}.get(metric, "log"), title=kind,
                   xlabel="map size (cells per side)", ylabel=ylabel)
            ax.grid(alpha=0.3, which="both")
        axes[0][0].legend(fontsize=8)
        fig.tight_layout()
        save(fig, figures, name + ".png")
    examples = df[df["run.path"].notna() & (df["seed"] == 1)] if "run.path" in df else df.iloc[0:0]
    cases = list(examples.groupby("map", sort=False))
    if cases:
        fig, axes = map_panels(len(cases), 4.5, 4.5)
        for ax, (name, r) in zip(axes, cases):
            size = r.iloc[0]["problem.size"]
            draw_grid(ax, np.asarray(r.iloc[0]["problem.grid"]).reshape(size, size) > 0)
            for _, run in r.iterrows():
                draw_route(ax, run["run.path"], None, lw=1.2, label=SCALE_LABEL[run["variant"]])
            ax.set_title(f"{name}, seed 1")
        axes[0].legend(fontsize=7)
        save(fig, figures, "scale_examples.png")


def deadline_tables(df):
    rows = []
    for (name, limit), r in df.groupby(["map", "problem.limit_s"], sort=False):
        walls = list(r["run.time_ms"])
        over = max((t / (limit * 1000) - 1) * 100 for t in walls)
        gaps = [gap(x, o) for x, o in zip(r["length"], r["problem.optimum"]) if math.isfinite(x)]
        rows.append([name, fixed(limit, 2), fixed(median(walls), 1), fixed(max(walls), 1),
                     ("+" if over >= 0 else "") + fixed(over, 1) + " %", f"{len(gaps)}/{len(r)}",
                     fixed(mean(r["run.iterations_run"]), 0), fixed(mean(gaps), 2) if gaps else "—",
                     fixed(median(r["run.first_iteration_ms"]), 1)])
    return provenance(df) + "\n" + table(
        ["map", "limit s", "wall median ms", "wall worst ms", "over (worst)", "routes", "iterations run", "gap avg %",
         "set-up + 1st iteration ms"], rows)


# ---------------------------------------------------------------- costs

def cost_summary(r):
    ok = r[r["run.success"]]
    gaps = [num(x) for x in r["extra.gap_pct"]]
    driven = lambda key: [num(d[key]) for d in ok["extra.driven"]]  # noqa: E731
    cells = [(d["lethal_cells"], d["inscribed_cells"]) for d in ok["extra.driven"]]
    return {"runs": len(r), "successes": len(ok), "capped": int(r["run.interrupted"].sum()),
            "gap": (median(gaps), max(gaps)) if gaps else None, "time": median(r["run.time_ms"]),
            "ratio": median([num(x) for x in r["extra.time_ratio"]]), "length": median(driven("length")),
            "turn": median(driven("turn_deg")), "clearance": min(driven("min_clearance"), default=INF),
            "median_clearance": median(driven("min_clearance")), "cell_cost": median(driven("mean_cell_cost")),
            "cost": median(driven("cost")), "lethal": sum(c[0] for c in cells), "inscribed": sum(c[1] for c in cells),
            "in_lethal": sum(1 for c in cells if c[0] + c[1] > 0), "peak": max(r["extra.peak_rss_mb"])}


def gap_cell(s):
    return "—" if s["gap"] is None else f"{fixed(s['gap'][0], 2)} / {fixed(s['gap'][1], 2)}"


def ratio_cell(x):
    return fixed(x, 2 if x < 10 else 1) + "×" if math.isfinite(x) else "—"


def costs_tables(df):
    out, verdicts, generated, notes = [provenance(df)], [], [], []
    for group, g in df.groupby("map", sort=False):
        by = {v: cost_summary(r) for v, r in g.groupby("variant", sort=False)}
        e, es = by["eaci"], by["eaci-smoothed"]
        problems = g[g["variant"] == "astar"].drop_duplicates("problem.name")
        firsts = g[g["variant"] == "astar"].groupby("problem.name", sort=False).first()
        diff = max([abs(num(a) - num(d)) / max(1e-12, num(d)) for a, d in zip(firsts["run.cost"], firsts["problem.dijkstra_cost"])]
                   + [0.0])
        diff = INF if math.isnan(diff) else diff
        if e["gap"] is None:
            verdict = "no runs"
        else:
            why = ([f"median {fixed(e['gap'][0], 2)} % > 1 %"] if e["gap"][0] > 1 else []) + \
                  ([f"worst {fixed(e['gap'][1], 2)} % > 3 %"] if e["gap"][1] > 3 else [])
            verdict = "met" if not why else "**missed** (" + ", ".join(why) + ")"
        same = ("yes (identical)" if diff == 0 else f"yes (≤ {diff:.0e})") if diff <= 1e-9 else f"**no** ({fixed(diff * 100, 4)} %)"
        verdicts.append([group, len(problems), e["runs"], same, gap_cell(e), verdict,
                         sum(s["in_lethal"] for s in by.values()), ratio_cell(e["ratio"]), ratio_cell(es["ratio"]),
                         gap_cell(es), ratio(es["turn"], e["turn"])])
        if group == "lab":
            res, rows = g.iloc[0]["problem.resolution"], []
            for pname, p in g.groupby("problem.name", sort=False):
                for i, (v, r) in enumerate(p.groupby("variant", sort=False)):
                    s = cost_summary(r)
                    rows.append(["" if i else pname, COST_LABEL[v], fixed(s["cost"], 2), gap_cell(s),
                                 fixed(s["length"] * res, 2), fixed(s["turn"], 0), fixed(s["clearance"] * res, 3),
                                 fixed(s["cell_cost"], 1), f"{s['lethal']} / {s['inscribed']}", ms(s["time"]),
                                 ratio_cell(s["ratio"])])
            lab = (f"#### Lab map ({g.iloc[0]['problem.size']} cells wide, {res:g} m per cell)\n\nMedians over "
                   f"{g['seed'].max()} seeds (A*: the same route each time).\n\n" + table(
                       ["start → goal (m)", "planner", "cost", "gap median / worst %", "length m", "turning °",
                        "min clearance m", "mean cell cost", "lethal / inscribed cells", "ms", "÷ A*"], rows))
            out_lab = lab
        else:
            blocked = f"{fixed(mean(problems['problem.obstacle_fraction']) * 100, 0)} → " \
                      f"{fixed(mean(problems['problem.blocked_fraction']) * 100, 0)} %"
            for i, (v, s) in enumerate(by.items()):
                routes = f"{s['successes']}/{s['runs']}" + (f" ({s['capped']} capped)" if s["capped"] else "")
                generated.append(["" if i else group, "" if i else blocked, COST_LABEL[v], routes, gap_cell(s),
                                  fixed(s["length"], 1), fixed(s["turn"], 0),
                                  f"{fixed(s['clearance'], 2)} / {fixed(s['median_clearance'], 2)}",
                                  fixed(s["cell_cost"], 1), f"{s['lethal']} / {s['inscribed']}", ms(s["time"]),
                                  ratio_cell(s["ratio"]), fixed(s["peak"], 1)])
            for _, p in problems.iterrows():
                for seed in p["problem.redrawn_map_seeds"]:
                    notes.append(f"- {group}: seed {p['problem.map_seed']}: map seed {seed} had no route once "
                                 f"inflated; used map seed {p['problem.map_seed_used']}")
        for _, r in g.iterrows():
            d = r["extra.driven"] if isinstance(r["extra.driven"], dict) else {}
            why = ([] if r["run.success"] else ["found no route"]) + \
                  (["hit the time budget (capped)"] if r["run.interrupted"] else []) + \
                  ([f"enters {d['lethal_cells']} lethal and {d['inscribed_cells']} inscribed cells"]
                   if d.get("lethal_cells", 0) + d.get("inscribed_cells", 0) else []) + \
                  (["smoothed a different grid route than its unsmoothed twin"] if r.get("extra.same_grid_route") is False else [])
            notes += [f"- {group}: {r['problem.name']}: {COST_LABEL[r['variant']]} seed {r['seed']} {w}" for w in why]
    out.append("#### Verdict per map set\n\n" + table(
        ["maps", "problems", "runs per planner", "A* = Dijkstra (worst rel. diff.)", "EACI gap median / worst %",
         "EACI: median ≤ 1 %, worst ≤ 3 %", "routes in lethal / inscribed cells (all planners)",
         "EACI ÷ A* time (median)", "EACI smoothed ÷ A* time", "EACI smoothed gap median / worst %",
         "turning: EACI smoothed ÷ EACI"], verdicts))
    if "lab" in set(df["map"]):
        out.append(out_lab)
    out.append("#### Generated maps (lengths and clearances in cells)\n\n*blocked after inflation*: obstacle cells of "
               "the map → cells of cost ≥ 253 after inflation (average over the seeds).\n\n" + table(
                   ["map", "blocked after inflation", "planner", "routes", "gap median / worst %", "length",
                    "turning °", "min clearance worst / median", "mean cell cost", "lethal / inscribed cells", "ms",
                    "÷ A*", "peak MiB"], generated))
    if notes:
        out.append("#### Notes\n\n" + "\n".join(notes) + "\n")
    return "\n".join(out)


def costs_figures(df, figures):
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.4))
    for ax, variant in zip(axes, ("eaci", "eaci-smoothed")):
        sel = df[(df["variant"] == variant) & (df["map"] != "lab")]
        groups = list(sel.groupby("map", sort=False))
        ax.boxplot([[num(x) for x in g["extra.gap_pct"]] for _, g in groups], labels=[n for n, _ in groups])
        ax.axhline(0, color="0.4", lw=0.8)
        ax.set(ylabel="cost over A*'s (%)", title=COST_LABEL[variant])
        ax.tick_params(axis="x", rotation=30)
    fig.tight_layout()
    save(fig, figures, "costs_gap.png")
    lab = df[(df["map"] == "lab") & df["problem.costs"].notna()] if "problem.costs" in df else df.iloc[0:0]
    if len(lab):
        costs = np.asarray(lab.iloc[0]["problem.costs"], dtype=float).reshape(-1, lab.iloc[0]["problem.size"])
        fig, ax = plt.subplots(figsize=(9, 6))
        ax.imshow(costs, cmap="Greys", vmin=0, vmax=255, interpolation="nearest")
        for _, r in lab[lab["seed"] == 1].iterrows():
            path = r["run.smoothed_path"] if isinstance(r.get("run.smoothed_path"), list) else r["run.path"]
            draw_route(ax, path, None, lw=1.6, label=COST_LABEL[r["variant"]])
        ax.legend(fontsize=8)
        ax.set_title("The lab's inflated costs and the routes of seed 1")
        save(fig, figures, "costs_lab.png")


# ---------------------------------------------------------------- scen

def scen_tables(df):
    problems = []
    for index, p in df.groupby("problem.index", sort=False):
        a, e = p[p["variant"] == "astar"].iloc[0], p[p["variant"] == "eaci"]
        opt = a["problem.optimal_length"]
        gaps = [(x / opt - 1) * 100 if opt > 0 else (0.0 if x <= 1e-4 else INF) for x in e["length"] if math.isfinite(x)]
        e_ms = median(e["run.time_ms"])
        problems.append({"a": a, "e": e, "opt": opt, "gaps": gaps, "e_ms": e_ms, "diff": a["length"] - opt,
                         "ratio": e_ms / a["run.time_ms"] if a["run.time_ms"] > 0 else INF})
    runs = [x for p in problems for x in p["e"]["length"]]
    solved = [p for p in problems if p["gaps"]]
    all_gaps = [g for p in problems for g in p["gaps"]]
    ratios = [p["ratio"] for p in problems if math.isfinite(p["ratio"])]
    first = df.iloc[0]
    out = [provenance(df), table(
        ["problems run", "A* mismatches", "EACI solved", "EACI optimal", "gap median", "gap mean", "gap worst",
         "time EACI/A* median", "A* total", "EACI total"],
        [[f"{len(problems)} of {first['problem.problems_in_file']}", sum(not abs(p["diff"]) <= 1e-4 for p in problems),
          f"{sum(math.isfinite(x) for x in runs)}/{len(runs)}",
          sum(1 for p in problems for x in p["e"]["length"] if abs(x - p["opt"]) <= 1e-4),
          fixed(median([mean(p["gaps"]) for p in solved]), 2) + " %",
          fixed(mean([mean(p["gaps"]) for p in solved]), 2) + " %", fixed(max(all_gaps, default=INF), 2) + " %",
          fixed(median(ratios), 1) + "×", ms(sum(p["a"]["run.time_ms"] for p in problems)) + " ms",
          ms(sum(df[df["variant"] == "eaci"]["run.time_ms"])) + " ms"]])]
    bands, rows = {}, []
    for p in problems:
        bands.setdefault(2 ** math.floor(math.log2(max(p["opt"], 1.0))), []).append(p)
    for lower in sorted(bands):
        b = bands[lower]
        rs = [p["ratio"] for p in b if math.isfinite(p["ratio"])]
        n_runs = sum(len(p["e"]) for p in b)
        rows.append([f"{lower:.0f}–{2 * lower:.0f}", len(b), f"{sum(len(p['gaps']) for p in b)}/{n_runs}",
                     fixed(median(rs), 2) + "×", fixed(max(rs, default=INF), 2) + "×",
                     fixed(median([mean(p["gaps"]) for p in b if p["gaps"]]), 2) + " %",
                     fixed(max([g for p in b for g in p["gaps"]], default=INF), 2) + " %",
                     ms(median([p["a"]["run.time_ms"] for p in b])), ms(median([p["e_ms"] for p in b]))])
    out.append("By route length (bands of the optimal length, cells; times are medians over the band's problems):\n\n"
               + table(["optimal length", "problems", "EACI solved", "time EACI/A* median", "EACI/A* worst",
                        "gap median", "gap worst", "A* ms", "EACI ms"], rows))
    return "\n".join(out)


# ---------------------------------------------------------------- front (issue #30)

FRONT_PAPER_ROWS = ("ACO", "IACO", "CMEACO", "MAACO", "EACI")
FRONT_EACI_LABEL = {"eaci-geodesic": "ours: EACI, geodesic islands", "eaci-paper": "ours: EACI, paper islands"}
FRONT_EACI_STYLE = {"eaci-geodesic": ("tab:green", "o"), "eaci-paper": ("tab:blue", "s")}


def front_paper_points(spec):
    """The paper's table rows for a map: {algorithm: (best length, corner angle °)} where both are given."""
    rows = {"ACO": spec.get("paper_aco"), "EACI": spec.get("paper_eaci")}
    rows.update(spec.get("paper_baselines") or {})
    return {a: (rows[a][2], rows[a][5]) for a in FRONT_PAPER_ROWS
            if rows.get(a) and rows[a][2] is not None and rows[a][5] is not None}


def nondominated(points):
    """The (length, angle) pairs no other pair beats in both (ties in both count once)."""
    pts = sorted(set((round(l, 6), round(a, 6)) for l, a in points))
    return [p for p in pts if not any(q != p and q[0] <= p[0] + 1e-9 and q[1] <= p[1] + 1e-9 for q in pts)]


def front_verdict(name, m, spec):
    """Whether the exact front holds a route no longer than the paper's EACI route (its best length,
    which the paper gives to 2 decimals) turning less than every algorithm of the paper's table."""
    paper = front_paper_points(spec)
    limit_len, limit_angle = paper["EACI"][0], min(a for _, a in paper.values())
    front = m[m["variant"] == "pareto"]
    fit = front[front["length"] <= limit_len + 0.005]
    least = fit.loc[fit["run.total_turn_deg"].idxmin()] if len(fit) else None
    lowest = front["run.total_turn_deg"].min()
    if least is not None and least["run.total_turn_deg"] < limit_angle:
        return (f"**{name}: yes.** The paper's EACI route is {limit_len:.2f} long; the least turning route no longer "
                f"than that turns {least['run.total_turn_deg']:.0f}° (length {least['length']:.4f}), below "
                f"{limit_angle:.0f}°, the least angle in the paper's table.")
    why = (f"the least turning route no longer than that turns {least['run.total_turn_deg']:.0f}° "
           f"(length {least['length']:.4f})" if least is not None else "no route is that short")
    return (f"**{name}: no.** The paper's EACI route is {limit_len:.2f} long and the least angle in the paper's table "
            f"is {limit_angle:.0f}°; {why}, and no route on this map at all turns less than {lowest:.0f}° (the front's "
            f"least turning end). The front shows it cannot be done on this map with this angle measure.")


def front_tables(df):
    specs = paper_maps()
    out = [provenance(df)]
    verdicts = []
    for name, m in df.groupby("map", sort=False):
        spec = specs[name]
        heading = m[m["variant"] == "heading"]
        front = m[m["variant"] == "pareto"].sort_values("length")
        front_pts = nondominated(zip(front["length"], front["run.total_turn_deg"]))
        rows = []
        for _, r in heading.iterrows():
            on = (round(r["length"], 6), round(r["run.total_turn_deg"], 6)) in front_pts
            rows.append([fixed(r["extra.turn_cost"], 2), fixed(r["length"], 4), fixed(r["run.total_turn_deg"], 0),
                         fixed(r["run.combined_cost"], 4), "yes" if on else "no"])
        out.append(f"#### {name} ({spec['table']})\n\nThe exact search over (cell, heading) states, one route per "
                   f"turn_cost (0: plain A*, whose tie among shortest routes is arbitrary):\n\n" + table(
                       ["turn_cost (per rad)", "length", "corner angle (°)", "combined cost", "on the front"], rows))
        out.append("The whole exact front (every Pareto-nondominated route, shortest first): " + ", ".join(
            f"{l:.4f} / {a:.0f}°" for l, a in front_pts) + ".\n")
        rows = []
        gaps = []
        eaci = m[m["variant"].str.startswith("eaci")]
        for (variant, turn_cost), runs in eaci.groupby(["variant", "extra.turn_cost"], sort=False):
            pts = [(round(l, 4), a) for l, a in zip(runs["length"], runs["run.total_turn_deg"]) if math.isfinite(l)]
            counts = {}
            for p in pts:
                counts[p] = counts.get(p, 0) + 1
            rows.append([FRONT_EACI_LABEL[variant], fixed(turn_cost, 2), f"{len(pts)}/{len(runs)}",
                         "; ".join(f"{l:.4f} / {a:.0f}° ×{n}" for (l, a), n in sorted(counts.items()))])
            # The combined optimum is reached on the front (a route off it is dominated); cost = length here.
            optimum = min(l + turn_cost * math.radians(a) for l, a in front_pts)
            ok = runs[np.isfinite(runs["length"])]
            gap = (ok["length"] + turn_cost * np.radians(ok["run.total_turn_deg"])) / optimum - 1.0
            gap = gap.where(gap.abs() > 1e-6, 0.0)  # the optimum itself up to the records' rounding: not "-0.00 %"
            gaps.append([FRONT_EACI_LABEL[variant].replace("ours: ", ""), fixed(turn_cost, 2), fixed(optimum, 4),
                         f"{int((gap <= 0.01 + 1e-12).sum())}/{len(runs)}", f"{100 * gap.mean():.2f} %",
                         f"{100 * gap.max():.2f} %", fixed(ok["run.iterations_to_converge"].mean(), 1),
                         fixed(ok["run.time_ms"].median(), 1)])
        for algorithm, (length, angle) in front_paper_points(spec).items():
            rows.append([f"paper: {algorithm} (best length)", "", "", f"{length:.2f} / {angle:.0f}°"])
        out.append(table(["routes", "turn_cost", "success", "length / corner angle (°) × seeds"], rows))
        out.append("EACI scoring turns against the exact optimum of the combined objective (length + turn_cost × "
                   "corner angle in radians; the least over the exact front):\n\n" + table(
                       ["EACI", "turn_cost", "optimum", "within 1 %", "gap mean", "gap worst",
                        "iterations to best (mean)", "time ms (median)"], gaps))
        verdicts.append("- " + front_verdict(name, m, spec))
    out.append("#### The question of issue #30\n\nA route no longer than the paper's EACI route with a total corner "
               "angle below every algorithm in the paper's table:\n\n" + "\n".join(verdicts) + "\n")
    return "\n".join(out)


def front_figures(df, figures):
    specs = paper_maps()
    for name, m in df.groupby("map", sort=False):
        spec = specs[name]
        fig, ax = plt.subplots(figsize=(7.2, 5.2))
        front = m[m["variant"] == "pareto"].sort_values("length")
        pts = nondominated(zip(front["length"], front["run.total_turn_deg"]))
        xs, ys = [p[0] for p in pts], [p[1] for p in pts]
        # The front as a staircase: a route of length x can turn as little as the front's point at or left of x.
        ax.step(xs + [xs[-1] + 0.6], ys + [ys[-1]], where="post", color="black", lw=1.2, alpha=0.5)
        ax.plot(xs, ys, "k-D", ms=6, lw=0, label="exact front (every nondominated route)")
        heading = m[m["variant"] == "heading"]
        ax.plot(heading["length"], heading["run.total_turn_deg"], "x", color="tab:red", ms=9, mew=1.6,
                label="exact (cell, heading) search, turn_cost sweep")
        jitter = {"eaci-geodesic": -0.04, "eaci-paper": 0.04}
        eaci = m[m["variant"].str.startswith("eaci")]
        priced = eaci["extra.turn_cost"].max()  # EACI unpriced (filled) and at the dearest turn_cost (hollow)
        for (variant, turn_cost), runs in eaci.groupby(["variant", "extra.turn_cost"], sort=False):
            if turn_cost not in (0, priced):
                continue
            ok = runs[np.isfinite(runs["length"])]
            color, marker = FRONT_EACI_STYLE[variant]
            counts = {}
            for l, a in zip(ok["length"], ok["run.total_turn_deg"]):
                counts[(round(l, 4), a)] = counts.get((round(l, 4), a), 0) + 1
            hollow = turn_cost != 0
            ax.scatter([k[0] + jitter[variant] for k in counts], [k[1] for k in counts],
                       s=[30 + 12 * n for n in counts.values()], marker=marker, alpha=0.75 if hollow else 0.55,
                       facecolors="none" if hollow else color, edgecolors=color if hollow else "black",
                       linewidths=1.6 if hollow else 0.5,
                       label=f"{FRONT_EACI_LABEL[variant]}, turn_cost {turn_cost:g}, {len(runs)} seeds (area ∝ seeds)")
        paper = front_paper_points(spec)
        ax.scatter([p[0] for p in paper.values()], [p[1] for p in paper.values()], marker="*", s=160,
                   color="gold", edgecolors="black", linewidths=0.7, zorder=5,
                   label="the paper's table (best length, corner angle)")
        same = {}  # algorithms the paper's table puts on one point share one label
        for algorithm, point in paper.items():
            same.setdefault(point, []).append(algorithm)
        for (length, angle), names in same.items():
            ax.annotate(", ".join(names), (length, angle), textcoords="offset points", xytext=(7, 5), fontsize=9)
        ax.axhline(min(a for _, a in paper.values()), color="0.5", ls=":", lw=1)
        ax.axvline(paper["EACI"][0], color="0.5", ls=":", lw=1)
        ax.set_xlabel("route length (cells)")
        ax.set_ylabel("total corner angle of the grid route (°)")
        ax.set_title(f"{name} ({spec['table']}): length against total corner angle\n"
                     "dotted: the paper's EACI length and the least angle in its table")
        ax.grid(alpha=0.3)
        legend = ax.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.13), ncol=2, frameon=False)
        for handle in getattr(legend, "legend_handles", None) or legend.legendHandles:
            if hasattr(handle, "set_sizes"):
                handle.set_sizes([60])
        save(fig, figures, f"front_{name.replace('paper-', '')}.png")


# ---------------------------------------------------------------- main

TABLES = {"paper": paper_tables, "sweep": sweep_tables, "front": front_tables, "scale": scale_tables, "deadline": deadline_tables,
          "costs": costs_tables, "scen": scen_tables}
FIGURES = {"paper": paper_figures, "sweep": sweep_figures, "front": front_figures, "scale": scale_figures, "costs": costs_figures}


def replace_block(doc, name, text):
    pattern = re.compile(r"(<!-- generated: " + re.escape(name) + r" -->\n).*?(<!-- end -->)", re.S)
    if not pattern.search(doc):
        raise SystemExit(f"bench_report.py: no '<!-- generated: {name} -->' ... '<!-- end -->' in the doc")
    return pattern.sub(lambda m: m.group(1) + "\n" + text.rstrip("\n") + "\n\n" + m.group(2), doc, count=1)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("studies", nargs="*", choices=STUDIES + [[]], default=[])
    parser.add_argument("--records", default="out/bench")
    parser.add_argument("--doc", default=os.path.join(ROOT, "docs", "benchmarks.md"))
    parser.add_argument("--figures", default=os.path.join(ROOT, "docs", "figures"))
    parser.add_argument("--stdout", action="store_true", help="print the tables; leave the doc and figures alone")
    args = parser.parse_args(argv)
    studies = args.studies or [s for s in STUDIES if os.path.exists(os.path.join(args.records, s + ".jsonl"))]
    doc = None if args.stdout else open(args.doc).read()
    for study in studies:
        df = load(os.path.join(args.records, study + ".jsonl"))
        blocks = TABLES[study](df)
        for name, text in (blocks if isinstance(blocks, dict) else {study: blocks}).items():
            if args.stdout:
                print(f"<!-- generated: {name} -->\n\n{text}\n<!-- end -->\n")
            else:
                doc = replace_block(doc, name, text)
        if not args.stdout and study in FIGURES:
            os.makedirs(args.figures, exist_ok=True)
            FIGURES[study](df, args.figures)
    if doc is not None:
        with open(args.doc, "w") as f:
            f.write(doc)
        print(f"bench_report.py: {', '.join(studies)}: tables in {args.doc}, figures in {args.figures}")


if __name__ == "__main__":
    main()
