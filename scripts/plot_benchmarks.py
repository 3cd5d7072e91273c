#!/usr/bin/env python3
"""Figures from eaci_bench's JSON results (matplotlib, Agg backend).

Usage: scripts/plot_benchmarks.py RESULTS.json [MORE.json ...] OUTDIR

Each JSON file is recognised by its "kind":
  paper  -> routes_<map>.png (paper Figs 17/22/25/28), convergence.png (Figs 18/23/26/29),
            convergence_time.png, lost_ants.png (Figs 19/24/27/30),
            pheromone_<map>_<strategy>.png (Figs 15/16/20/21)
  sweep  -> sweep_<parameter>.png (Figs 11-14), aco_rho.png
  scale  -> scale_time.png, scale_gap.png, scale_memory.png, scale_examples.png
  costs  -> costs_gap.png (cost over A*'s by map size), costs_lab.png (lab routes on the cost map)
Needs Debian's python3-matplotlib and python3-numpy (run with /usr/bin/python3).
"""

import json
import math
import os
import sys

import matplotlib
import matplotlib.ticker

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.colors import ListedColormap, LogNorm  # noqa: E402

DPI = 110
ALGORITHM_STYLE = {
    "astar": {"color": "0.45", "label": "A* (optimum)", "ls": "--"},
    "aco": {"color": "tab:red", "label": "classic ACO", "ls": "-"},
    "aco-strong": {"color": "tab:orange", "label": "classic ACO, τ0 1, ρ 0.3", "ls": "-"},
    "eaci-paper": {"color": "tab:blue", "label": "EACI, paper islands", "ls": "-"},
    "eaci-geodesic": {"color": "tab:green", "label": "EACI, geodesic islands", "ls": "-"},
}
SCALE_STYLE = {
    "astar": ("0.3", "o", "A*"),
    "eaci-1t": ("tab:green", "s", "EACI, 1 thread"),
    "eaci-all": ("tab:olive", "s", "EACI, all cores"),
    "eaci-early-1t": ("tab:cyan", "^", "EACI early stop, 1 thread"),
    "eaci-early-all": ("tab:purple", "^", "EACI early stop, all cores"),
    "aco-1t": ("tab:red", "v", "classic ACO, 1 thread"),
    "aco-all": ("tab:orange", "v", "classic ACO, all cores"),
}
MAP_CMAP = ListedColormap(["white", "black"])


def save(fig, outdir, name):
    path = os.path.join(outdir, name)
    fig.savefig(path, dpi=DPI, bbox_inches="tight")
    plt.close(fig)
    print(path)


def finite(values):
    return [v if v is not None else math.nan for v in values]


def pretty(name):
    return name.replace("paper-", "").replace("-alt-", " alt ")


# ---------------------------------------------------------------- map drawing

def draw_grid(ax, grid, light=False, lines=True):
    """Obstacles black (grey when light), free cells white; cell (r, c) centred at x = c, y = r."""
    g = np.asarray(grid, dtype=float)
    cmap = ListedColormap(["white", "0.55"]) if light else MAP_CMAP
    ax.imshow(g, cmap=cmap, vmin=0, vmax=1, interpolation="nearest", origin="upper")
    h, w = g.shape
    if lines and max(h, w) <= 60:  # grid lines on the paper's small maps
        ax.set_xticks(np.arange(-0.5, w, 1), minor=True)
        ax.set_yticks(np.arange(-0.5, h, 1), minor=True)
        ax.grid(which="minor", color="0.8", linewidth=0.3)
        ax.tick_params(which="minor", length=0)
    ax.set_xticks([])
    ax.set_yticks([])


def draw_route(ax, cells, color, label=None, ls="-", lw=2.0):
    if not cells:
        return
    rows = [c[0] for c in cells]
    cols = [c[1] for c in cells]
    ax.plot(cols, rows, color=color, ls=ls, lw=lw, label=label, solid_capstyle="round")


def draw_endpoints(ax, start, goal, size=9):
    ax.plot(start[1], start[0], "o", color="tab:orange", markersize=size, markeredgecolor="black", zorder=5)
    ax.plot(goal[1], goal[0], "*", color="gold", markersize=size + 5, markeredgecolor="black", zorder=5)


# ---------------------------------------------------------------- paper figures

def best_run(algorithm):
    return algorithm["runs"][algorithm["summary"]["best_run_index"]]


def median_run(algorithm):
    return algorithm["runs"][algorithm["summary"]["median_run_index"]]


def plot_routes(m, outdir):
    algorithms = m["algorithms"]
    fig, axes = plt.subplots(1, len(algorithms) + 1, figsize=(4.2 * (len(algorithms) + 1), 4.6))
    panels = [("astar", {"path": m["astar"]["path"], "length": m["astar"]["length"],
                         "total_turn_deg": m["astar"]["total_turn_deg"], "islands": []})]
    panels += [(a["key"], best_run(a)) for a in algorithms]
    for ax, (key, run) in zip(axes, panels):
        style = ALGORITHM_STYLE[key]
        draw_grid(ax, m["grid"])
        if key != "astar":
            draw_route(ax, m["astar"]["path"], "0.6", ls="--", lw=1.2)
        draw_route(ax, run["path"], style["color"], lw=2.4)
        islands = run.get("islands") or []
        if key.startswith("eaci") and len(islands) > 2:
            ax.plot([c[1] for c in islands[1:-1]], [c[0] for c in islands[1:-1]], "D", color="magenta",
                    markersize=5, markeredgecolor="black", zorder=4)
        draw_endpoints(ax, m["start"], m["goal"])
        seed = f", seed {run['seed']}" if "seed" in run else ""
        ax.set_title(f"{style['label']}{seed}\nlength {run['length']:.4f}, turns {run['total_turn_deg']:.0f}°",
                     fontsize=10)
    fig.suptitle(f"{pretty(m['name'])}: best route of each planner (dashed grey: A*; magenta: islands)",
                 fontsize=12)
    save(fig, outdir, f"routes_{m['name']}.png")


def map_axes(maps, width=5.0, height=3.6):
    cols = 3 if len(maps) > 4 else 2
    rows = math.ceil(len(maps) / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(width * cols, height * rows), squeeze=False)
    for ax in axes.flat[len(maps):]:
        ax.axis("off")
    return fig, axes.flat


def plot_convergence(data, outdir):
    maps = data["maps"]
    fig, axes = map_axes(maps)
    for ax, m in zip(axes, maps):
        for a in m["algorithms"]:
            style = ALGORITHM_STYLE[a["key"]]
            run = median_run(a)
            x = np.arange(1, len(run["best_length_so_far"]) + 1)
            ax.plot(x, finite(run["best_length_so_far"]), color=style["color"], lw=2, label=style["label"])
            ax.plot(x, finite(run["iteration_best_length"]), color=style["color"], lw=0.8, alpha=0.45)
        ax.axhline(m["astar"]["length"], color="0.3", ls="--", lw=1, label="A* optimum")
        paper = m["paper"]["eaci"]
        if paper:
            ax.axhline(paper["best_length"], color="tab:purple", ls=":", lw=1.2, label="paper's EACI best")
        ax.set_title(pretty(m["name"]), fontsize=11)
        ax.set_xlabel("iteration")
        ax.set_ylabel("route length (cells)")
        ax.set_xlim(1, 100)
        top = max(max(x for x in finite(median_run(a)["iteration_best_length"]) if not math.isnan(x))
                  for a in m["algorithms"])
        ax.set_ylim(m["astar"]["length"] * 0.97, min(top, m["astar"]["length"] * 1.6) * 1.02)
        ax.grid(alpha=0.3)
    handles, labels = axes[0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=len(labels), fontsize=9, frameon=False)
    fig.suptitle("Convergence, median run of each planner (thick: best so far; thin: best of the iteration)",
                 fontsize=12)
    fig.tight_layout(rect=(0, 0.05, 1, 1))
    save(fig, outdir, "convergence.png")


def plot_convergence_time(data, outdir):
    maps = [m for m in data["maps"] if m["paper"]["eaci"]]
    fig, axes = map_axes(maps, width=6.0, height=5.2)
    for ax, m in zip(axes, maps):
        for a in m["algorithms"]:
            style = ALGORITHM_STYLE[a["key"]]
            run = median_run(a)
            ax.step(run["iteration_end_ms"], finite(run["best_length_so_far"]), where="post", color=style["color"],
                    lw=2, label=f"{style['label']} (best after {run['time_to_best_ms']:.1f} ms)")
        ax.axhline(m["astar"]["length"], color="0.3", ls="--", lw=1, label="A* optimum")
        ax.set_xscale("log")
        ax.set_title(pretty(m["name"]), fontsize=11)
        ax.set_xlabel("wall time (ms, one thread)")
        ax.set_ylabel("best route length so far")
        ax.set_ylim(m["astar"]["length"] * 0.98, m["astar"]["length"] * 1.45)
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.16), ncol=2, frameon=False)
    fig.suptitle("Best route so far against wall time (median run)", fontsize=12)
    fig.tight_layout()
    save(fig, outdir, "convergence_time.png")


def plot_lost_ants(data, outdir):
    maps = data["maps"]
    fig, axes = map_axes(maps, width=5.6, height=4.6)
    for ax, m in zip(axes, maps):
        for a in m["algorithms"]:
            style = ALGORITHM_STYLE[a["key"]]
            lost = np.array([r["lost_ants_per_iteration"] for r in a["runs"]], dtype=float)
            x = np.arange(1, lost.shape[1] + 1)
            ax.plot(x, lost.mean(axis=0), color=style["color"], lw=1.8,
                    label=f"{style['label']} ({a['summary']['avg_lost_ants']:.1f} per run)")
        ax.set_title(pretty(m["name"]), fontsize=11)
        ax.set_xlabel("iteration (log scale)")
        ax.set_ylabel(f"lost ants (of 50), mean of {len(m['algorithms'][0]['runs'])} runs")
        ax.set_xscale("log")
        ax.set_xlim(1, 100)
        ax.set_ylim(0, 51)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.2), ncol=2, frameon=False)
    fig.suptitle("Lost ants per iteration (totals per run in brackets)", fontsize=12)
    fig.tight_layout()
    save(fig, outdir, "lost_ants.png")


def plot_pheromone(m, algorithm, outdir):
    snapshots = algorithm["pheromone_snapshots"]
    if not snapshots:
        return
    grid = np.asarray(m["grid"], dtype=bool)
    fields = [np.asarray(s["strongest"], dtype=float).reshape(grid.shape) for s in snapshots]
    free_values = np.concatenate([f[~grid] for f in fields])
    vmax = free_values.max()
    vmin = max(free_values[free_values > 0].min(), vmax * 1e-6)
    fig, axes = plt.subplots(2, 3, figsize=(12.5, 8.2), layout="constrained")
    image = None
    for ax, snapshot, field in zip(axes.flat, snapshots, fields):
        shown = np.ma.masked_where(grid, np.clip(field, vmin, vmax))
        cmap = plt.get_cmap("viridis").copy()
        cmap.set_bad("black")
        image = ax.imshow(shown, cmap=cmap, norm=LogNorm(vmin=vmin, vmax=vmax), interpolation="nearest")
        draw_endpoints(ax, m["start"], m["goal"], size=6)
        title = "initial pheromone" if snapshot["iteration"] == 0 else f"after iteration {snapshot['iteration']}"
        ax.set_title(title, fontsize=11)
        ax.set_xticks([])
        ax.set_yticks([])
    last = axes.flat[len(snapshots)] if len(snapshots) < 6 else None
    if last is not None:
        run = next(r for r in algorithm["runs"] if r["seed"] == algorithm["pheromone_snapshots_seed"])
        draw_grid(last, m["grid"])
        draw_route(last, run["path"], ALGORITHM_STYLE[algorithm["key"]]["color"], lw=2.4)
        islands = run.get("islands") or []
        last.plot([c[1] for c in islands[1:-1]], [c[0] for c in islands[1:-1]], "D", color="magenta",
                  markersize=6, markeredgecolor="black", zorder=4)
        draw_endpoints(last, m["start"], m["goal"], size=6)
        last.set_title(f"this run's route ({run['length']:.2f}), islands", fontsize=11)
        for ax in axes.flat[len(snapshots) + 1:]:
            ax.axis("off")
    fig.colorbar(image, ax=list(axes.flat), shrink=0.7, label="strongest pheromone leaving the cell (log scale)")
    fig.suptitle(f"{pretty(m['name'])}: {ALGORITHM_STYLE[algorithm['key']]['label']}, seed "
                 f"{algorithm['pheromone_snapshots_seed']} (obstacles black)", fontsize=12)
    strategy = algorithm["key"].replace("eaci-", "")
    save(fig, outdir, f"pheromone_{m['name']}_{strategy}.png")


def plot_paper(data, outdir):
    for m in data["maps"]:
        plot_routes(m, outdir)
        for a in m["algorithms"]:
            if a["key"].startswith("eaci"):
                plot_pheromone(m, a, outdir)
    plot_convergence(data, outdir)
    plot_convergence_time(data, outdir)
    plot_lost_ants(data, outdir)


# ---------------------------------------------------------------- sweep figures

SWEEP_METRICS = [("avg_length", "average route length"), ("avg_iterations", "average iterations"),
                 ("avg_lost_ants", "average lost ants")]
STRATEGY_COLOR = {"paper": "tab:blue", "geodesic": "tab:green"}
MAP_LINESTYLE = ["-", "--", ":", "-."]


def symlog_axis(ax):
    """Linear below 1, logarithmic above, with plain-number ticks."""
    ax.set_yscale("symlog", linthresh=1.0)
    top = max(ax.get_ylim()[1], 1.0) * 1.6  # room above the highest marker
    ax.set_ylim(top=top)
    ticks = [t for t in [0, 0.5, 1, 2, 5, 10, 20, 50, 100, 200, 500, 1000, 2000, 5000] if t <= top * 1.05]
    ax.set_yticks(ticks)
    ax.yaxis.set_major_formatter(matplotlib.ticker.FuncFormatter(lambda v, _: f"{v:g}"))
    ax.yaxis.set_minor_locator(matplotlib.ticker.NullLocator())


def plot_eaci_sweep(data, axis, outdir):
    points = [p for p in data["eaci_points"] if p["parameter"] == axis["parameter"]]
    if not points:
        return
    maps = list(dict.fromkeys(p["map"] for p in points))
    strategies = list(dict.fromkeys(p["strategy"] for p in points))
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.2))
    for ax, (metric, label) in zip(axes, SWEEP_METRICS):
        for mi, m in enumerate(maps):
            for s in strategies:
                sel = sorted((p for p in points if p["map"] == m and p["strategy"] == s), key=lambda p: p["value"])
                ax.plot([p["value"] for p in sel], finite([p["summary"][metric] for p in sel]), marker="o",
                        ms=4, color=STRATEGY_COLOR.get(s, "k"), ls=MAP_LINESTYLE[mi % 4],
                        label=f"{pretty(m)}, {s} islands")
        if axis["parameter"] == "lambda":
            ax.set_xscale("log")
        if metric == "avg_lost_ants":
            symlog_axis(ax)
        ax.set_xlabel(f"{axis['symbol']} ({axis['parameter']})")
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=8)
    runs = data["settings"]["runs"]
    fig.suptitle(f"EACI against {axis['symbol']} (the paper's {axis['figure']}); N = 6 unless swept, "
                 f"{runs} seeds per point", fontsize=12)
    fig.tight_layout()
    save(fig, outdir, f"sweep_{axis['parameter']}.png")


def plot_aco_rho(data, outdir):
    points = data["aco_rho_points"]
    if not points:
        return
    maps = list(dict.fromkeys(p["map"] for p in points))
    taus = data["aco_tau0_values"]
    colors = plt.get_cmap("plasma")(np.linspace(0.0, 0.8, len(taus)))
    fig, axes = plt.subplots(2, len(maps), figsize=(4.2 * len(maps), 7.5), squeeze=False)
    for col, m in enumerate(maps):
        for row, (key, label) in enumerate([("iterations_ratio", "avg iterations, ours ÷ paper"),
                                            ("lost_ants_ratio", "avg lost ants, ours ÷ paper")]):
            ax = axes[row][col]
            ax.axhspan(0.5, 2.0, color="tab:green", alpha=0.12, label="within a factor 2")
            ax.axhline(1.0, color="tab:green", lw=0.8)
            for tau, color in zip(taus, colors):
                sel = sorted((p for p in points if p["map"] == m and p["tau0"] == tau), key=lambda p: p["rho"])
                ax.plot([p["rho"] for p in sel], [p[key] for p in sel], marker="o", ms=4, color=color,
                        label=f"τ0 = {tau:g}")
            ax.set_yscale("log")
            ax.set_ylim(0.01, 5)
            ax.set_xlabel("ρ (aco_rho)")
            ax.set_ylabel(label)
            ax.set_title(pretty(m), fontsize=11)
            ax.grid(alpha=0.3, which="both")
    axes[0][0].legend(fontsize=8, loc="lower left")
    fig.suptitle("Classic ACO against the paper's ACO row: evaporation ρ and initial pheromone τ0 (Q = 100)",
                 fontsize=12)
    fig.tight_layout()
    save(fig, outdir, "aco_rho.png")


def plot_sweep(data, outdir):
    for axis in data["eaci_axes"]:
        plot_eaci_sweep(data, axis, outdir)
    plot_aco_rho(data, outdir)


# ---------------------------------------------------------------- scale figures

def scale_series(data, kind, key, metric):
    """Sizes, values, and whether every run of that case found a route."""
    xs, ys, complete = [], [], []
    for c in data["cases"]:
        if c["kind"] != kind:
            continue
        v = next((v for v in c["variants"] if v["key"] == key), None)
        if v is None or not v["runs"]:
            continue
        value = metric(v)
        if value is None or (isinstance(value, float) and math.isnan(value)):
            continue
        xs.append(c["size"])
        ys.append(value)
        complete.append(v["summary"]["successes"] == v["summary"]["runs"])
    return xs, ys, complete


HOLLOW_NOTE = "hollow marker: not every run found a route"


def scale_panels(data, title, ylabel, metric, keys, outdir, name, logy=True, note=HOLLOW_NOTE, symlog=False):
    kinds = data["settings"]["kinds"]
    fig, axes = plt.subplots(1, len(kinds), figsize=(6.4 * len(kinds), 4.8), squeeze=False)
    for ax, kind in zip(axes[0], kinds):
        for key in keys:
            color, marker, label = SCALE_STYLE[key]
            xs, ys, complete = scale_series(data, kind, key, metric)
            if not xs:
                continue
            ax.plot(xs, ys, color=color, label=label, lw=1.6, marker=marker, ms=7)
            failed = [(x, y) for x, y, ok in zip(xs, ys, complete) if not ok]
            if failed:  # hollow white marker over the filled one: not every run found a route
                ax.plot([x for x, _ in failed], [y for _, y in failed], ls="none", marker=marker, ms=7,
                        markerfacecolor="white", markeredgecolor=color)
        ax.set_xscale("log")
        if logy:
            ax.set_yscale("log")
            ax.yaxis.set_major_formatter(matplotlib.ticker.FuncFormatter(lambda v, _: f"{v:g}"))
            ax.yaxis.set_minor_formatter(matplotlib.ticker.FuncFormatter(
                lambda v, _: f"{v:g}" if f"{v:g}"[0] in "25" else ""))
        if symlog:  # linear below 1, logarithmic above
            symlog_axis(ax)
            ax.set_ylim(bottom=-0.05)
        sizes = data["settings"]["sizes"]
        ax.set_xticks(sizes)
        ax.set_xticklabels([f"{s}×{s}" for s in sizes], fontsize=8)
        ax.minorticks_off()
        ax.set_xlabel("map size (cells)")
        ax.set_ylabel(ylabel)
        ax.set_title(f"{kind} maps", fontsize=11)
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=8)
    fig.suptitle(title + (f"\n{note}" if note else ""), fontsize=12)
    fig.tight_layout()
    save(fig, outdir, name)


def plot_scale_examples(data, outdir):
    examples = data.get("examples") or []
    if not examples:
        return
    kinds = list(dict.fromkeys(ex["kind"] for ex in examples))
    sizes = sorted(set(ex["size"] for ex in examples))
    fig, axes = plt.subplots(len(kinds), len(sizes), figsize=(4.6 * len(sizes), 4.8 * len(kinds)), squeeze=False)
    for ax in axes.flat:
        ax.axis("off")
    for ex in examples:
        ax = axes[kinds.index(ex["kind"])][sizes.index(ex["size"])]
        ax.axis("on")
        draw_grid(ax, ex["grid"], light=True, lines=False)
        for key, lw in [("astar", 2.6), ("aco-1t", 1.2), ("eaci-1t", 1.4)]:
            if key in ex["routes"]:
                color, _, label = SCALE_STYLE[key]
                draw_route(ax, ex["routes"][key], color, label=label, lw=lw)
        draw_endpoints(ax, ex["start"], ex["goal"], size=7)
        ax.set_title(f"{ex['kind']} {ex['size']}×{ex['size']} (seed {ex['seed']})", fontsize=11)
    axes[0][0].legend(fontsize=9, loc="lower left")
    fig.suptitle("Generated maps with the routes of seed 1 (no corner cutting; ACO missing where it found none)",
                 fontsize=12)
    fig.tight_layout(rect=(0, 0, 1, 0.97))
    save(fig, outdir, "scale_examples.png")


def plot_scale(data, outdir):
    all_keys = list(SCALE_STYLE)
    scale_panels(data, "Time per plan against map size (median over the seeds)", "wall time per plan (ms)",
                 lambda v: v["summary"]["median_time_ms"], all_keys, outdir, "scale_time.png")

    def gap(v):
        return v["avg_gap_pct"] if v["summary"]["successes"] > 0 else None

    scale_panels(data, "Route length over the A* optimum (successful runs)", "gap to A* (%), linear below 1", gap,
                 ["eaci-1t", "eaci-early-1t", "aco-1t"], outdir, "scale_gap.png", logy=False,
                 note="classic ACO is missing where none of its ants reached the goal; " + HOLLOW_NOTE, symlog=True)
    scale_panels(data, "Success rate", "runs with a route (%)",
                 lambda v: 100.0 * v["summary"]["success_rate"], ["astar", "eaci-1t", "eaci-early-1t", "aco-1t"],
                 outdir, "scale_success.png", logy=False, note=None)
    scale_panels(data, "Peak memory of the process running one plan", "peak resident set (MiB)",
                 lambda v: v["max_peak_rss_mb"], ["astar", "eaci-1t", "eaci-all", "aco-1t"], outdir,
                 "scale_memory.png")
    plot_scale_examples(data, outdir)


# ---------------------------------------------------------------- cost-aware figures

COST_STYLE = {
    "astar": ("0.3", "o", "A*", "--"),
    "astar-smoothed": ("tab:blue", "D", "A*, smoothed", "-"),
    "eaci-1t": ("tab:green", "s", "EACI", "-"),
    "eaci-smoothed-1t": ("tab:purple", "^", "EACI, smoothed", "-"),
}


def draw_costs(ax, rows):
    """A costmap_2d char map: 0 white, 252 dark grey, 253 (inscribed) light red, 254/255 black."""
    g = np.asarray(rows, dtype=float)
    rgb = np.empty(g.shape + (3,))
    shade = 1.0 - 0.75 * np.clip(g, 0, 252) / 252.0
    for k in range(3):
        rgb[..., k] = shade
    rgb[g == 253] = (1.0, 0.75, 0.75)
    rgb[g >= 254] = (0.0, 0.0, 0.0)
    ax.imshow(rgb, interpolation="nearest", origin="upper")
    ax.set_xticks([])
    ax.set_yticks([])


def cost_route(problem, key):
    v = next((v for v in problem["variants"] if v["key"] == key), None)
    if v is None or not v["runs"]:
        return None
    run = v["runs"][0]
    return run.get("smoothed_path") or run.get("path")


def plot_costs_gap(data, outdir):
    groups = [g for g in data["groups"] if not g["lab"]]
    kinds = list(dict.fromkeys(g["kind"] for g in groups))
    if not kinds:
        return
    fig, axes = plt.subplots(1, len(kinds), figsize=(6.4 * len(kinds), 4.8), squeeze=False)
    for ax, kind in zip(axes[0], kinds):
        sizes = sorted(g["size"] for g in groups if g["kind"] == kind)
        ax.axhline(1.0, color="tab:red", lw=0.9, ls=":", label="target: median 1 %")
        ax.axhline(3.0, color="tab:red", lw=0.9, ls="--", label="target: worst 3 %")
        ax.axhline(0.0, color="0.3", lw=0.9, label="A* (cheapest 8-connected route)")
        for key, dx in [("eaci-1t", -0.03), ("eaci-smoothed-1t", 0.0), ("astar-smoothed", 0.03)]:
            color, marker, label, _ = COST_STYLE[key]
            xs, med, lo, hi = [], [], [], []
            for g in sorted((g for g in groups if g["kind"] == kind), key=lambda g: g["size"]):
                gaps = [r["gap_pct"] for p in g["problems"] for v in p["variants"] if v["key"] == key
                        for r in v["runs"] if r["gap_pct"] is not None]
                if not gaps:
                    continue
                xs.append(g["size"] * (1 + dx))
                med.append(float(np.median(gaps)))
                lo.append(min(gaps))
                hi.append(max(gaps))
            ax.plot(xs, med, color=color, marker=marker, ms=7, lw=1.6, label=f"{label}: median, bar = range")
            ax.vlines(xs, lo, hi, color=color, lw=2.0, alpha=0.6)
        ax.set_xscale("log")
        ax.set_xticks(sizes)
        ax.set_xticklabels([f"{s}×{s}" for s in sizes], fontsize=8)
        ax.minorticks_off()
        ax.set_xlabel("map size (cells)")
        ax.set_ylabel("cost over A*'s (%)")
        ax.set_title(f"{kind} maps, inflated", fontsize=11)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7.5, loc="upper left")
    fig.suptitle("Route cost over A*'s on inflated generated maps (smoothed: cost of the straight segments)",
                 fontsize=12)
    fig.tight_layout()
    save(fig, outdir, "costs_gap.png")


def plot_costs_lab(data, outdir):
    lab = next((g for g in data["groups"] if g["lab"]), None)
    if lab is None or not lab["problems"] or "example_costs" not in lab["problems"][0]:
        return
    costs = lab["problems"][0]["example_costs"]
    wanted = [p for p in lab["problems"] if cost_route(p, "eaci-1t")][:4]
    fig, axes = plt.subplots(2, 2, figsize=(11.5, 7.6), squeeze=False)
    for ax in axes.flat[len(wanted):]:
        ax.axis("off")
    for ax, p in zip(axes.flat, wanted):
        draw_costs(ax, costs)
        for key, lw in [("astar", 2.8), ("eaci-1t", 1.6), ("eaci-smoothed-1t", 1.8)]:
            route = cost_route(p, key)
            if route:
                color, _, label, ls = COST_STYLE[key]
                draw_route(ax, route, color, label=label, ls=ls, lw=lw)
        draw_endpoints(ax, p["start"], p["goal"], size=7)
        ax.set_title(p["name"], fontsize=10)
    axes[0][0].legend(fontsize=8, loc="lower right")
    res = lab["resolution"]
    infl = data["settings"]["lab_inflation_m"]
    fig.suptitle(f"Lab map ({res} m cells), inflation radius {infl['inflation_radius']} m, inscribed "
                 f"{infl['inscribed_radius']} m (light red), cost_scaling_factor {infl['cost_scaling_factor']}: "
                 "seed-1 routes", fontsize=11)
    fig.tight_layout(rect=(0, 0, 1, 0.96))
    save(fig, outdir, "costs_lab.png")


def plot_costs(data, outdir):
    plot_costs_gap(data, outdir)
    plot_costs_lab(data, outdir)


def main(argv):
    if len(argv) < 3:
        sys.stderr.write(__doc__)
        return 2
    outdir = argv[-1]
    os.makedirs(outdir, exist_ok=True)
    for path in argv[1:-1]:
        with open(path) as f:
            data = json.load(f)
        kind = data.get("kind")
        if kind == "paper":
            plot_paper(data, outdir)
        elif kind == "sweep":
            plot_sweep(data, outdir)
        elif kind == "scale":
            plot_scale(data, outdir)
        elif kind == "costs":
            plot_costs(data, outdir)
        else:
            sys.stderr.write(f"{path}: unknown kind {kind!r}, skipped\n")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
