// The iteration loop of an ant colony (Steps 4-6): m ants per iteration, then a pheromone
// update, for Nc_max iterations, keeping the best complete route over all iterations. Routes
// rank by their cost L_k (AntRoute::cost; the length on a binary map). The walk, the update and
// the rank of equally cheap routes are the variant's rules (aco/variants.hpp).
#pragma once

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <thread>
#include <vector>

#include "eaci/aco/ant_walk.hpp"
#include "eaci/aco/colony_parameters.hpp"
#include "eaci/aco/pheromone_update.hpp"
#include "eaci/aco/variants.hpp"
#include "eaci/parallel/stop_poll.hpp"
#include "eaci/parallel/worker_group.hpp"

namespace eaci {

struct ColonyRun {
  std::vector<std::uint32_t> best_cells;  // grid indices of the best route, S first; empty if none
  double best_cost = std::numeric_limits<double>::infinity();
  int best_iteration = 0;                 // iteration (1-based) that first found best_cost
  int iterations_run = 0;
  bool stopped_early = false;             // early_stop_iterations without improvement, or stop_gap reached
  bool interrupted = false;               // should_stop() said so
  std::vector<int> ants_per_iteration;       // ants that walked: m, fewer where stop_gap ended the iteration
  std::vector<int> lost_ants_per_iteration;  // of the ants that walked
  std::vector<double> iteration_best_cost;  // +infinity where no ant completed
  std::vector<double> best_cost_so_far;     // +infinity until a route is found
};

// StopCheck (parallel/stop_poll.hpp) is asked between iterations with the number of iterations
// done, and every few thousand steps of each ant's walk, on the thread that walks it.
// Called after each iteration's pheromone update (e.g. to record snapshots), with the field and
// the region whose cells index it (strongestPheromoneByGridCell maps it onto the grid).
using IterationObserver = std::function<void(int iteration, const PheromoneField&, const ColonyRegion&)>;

inline int resolveThreadCount(int requested) {
  if (requested > 0) return requested;
  const unsigned hw = std::thread::hardware_concurrency();
  return hw == 0 ? 1 : static_cast<int>(hw);
}

// The threads a colony may walk its ants on: params.threads (0 = all cores), at most one per ant.
inline int colonyThreads(const ColonyParameters& params) { return std::min(resolveThreadCount(params.threads), params.ants); }
// The threads it does walk them on: those, but one alone on a region of fewer than
// kCellsForWorkers cells, whose walks are too short to pay for waking another thread (the
// result is the same on any number).
constexpr std::size_t kCellsForWorkers = 1024;
inline int colonyWorkers(const ColonyParameters& params, std::size_t region_cells) {
  return region_cells < kCellsForWorkers ? 1 : colonyThreads(params);
}

// What a colony keeps from one run to the next when its caller keeps it (the planner's
// workspace, PlanOptions::workspace): the ants' routes, each worker's walker, the worker
// threads, and the memory of the region and pheromone field the solvers build each plan. A
// run then starts no threads and allocates (and page-faults) almost nothing on a map it has
// planned on before.
struct ColonyWorkspace {
  // What one worker writes at every step, on cache lines of its own (two workers writing to
  // one line would make each wait for the other).
  struct alignas(64) WorkerState {
    AntWalker walker;  // reuses its memory from walk to walk
    AntRoute scratch;  // the route being walked
  };
  std::vector<AntRoute> routes;           // one per ant
  std::vector<WorkerState> worker_state;  // one per worker
  std::unique_ptr<WorkerGroup> workers;   // worker_state.size() threads, the caller's included (group())
  ColonyRegion region;                    // the last plan's, its memory for the next
  PheromoneField pheromone;               // likewise

  // Room for `ants` routes and `threads` workers (the threads already started stay when their
  // number is the same; when it changes, a reconfiguration, the old group is destroyed off the
  // planning thread: its destructor joins its threads, which the plan does not wait for).
  void prepare(int ants, int threads) {
    routes.resize(static_cast<std::size_t>(ants));
    for (AntRoute& route : routes) route.complete = false;
    if (worker_state.size() != static_cast<std::size_t>(threads)) {
      destroyOffThisThread(std::move(workers));
      worker_state = std::vector<WorkerState>(static_cast<std::size_t>(threads));
    }
  }
  // The worker threads, started on first use.
  WorkerGroup& group() {
    if (!workers) workers = std::make_unique<WorkerGroup>(static_cast<int>(worker_state.size()));
    return *workers;
  }
};

// `Rules`: ClassicAcoRules, EaciRules, MaacoRules (aco/variants.hpp).
template <class Rules>
class Colony {
 public:
  // `cheapest_cost`: the cost of a cheapest route through the waypoints when known (geodesic
  // islands), for stop_gap; +infinity when not. `workspace`: routes, walkers and threads kept
  // by the caller between runs (null: the colony's own).
  Colony(const WalkSetup& setup, PheromoneField& field, const ColonyParameters& params, Rules rules,
         double cheapest_cost = std::numeric_limits<double>::infinity(), ColonyWorkspace* workspace = nullptr)
      : setup_(setup), field_(field), params_(params), rules_(std::move(rules)),
        good_enough_cost_(std::isfinite(cheapest_cost)
                              ? cheapest_cost * (1.0 + params.stop_gap) + 1e-9 * std::max(1.0, cheapest_cost)
                              : -std::numeric_limits<double>::infinity()),
        workspace_(workspace != nullptr ? *workspace : own_workspace_), routes_(workspace_.routes),
        worker_state_(workspace_.worker_state),
        on_workers_(colonyWorkers(params, setup.region.size()) > 1) {
    workspace_.prepare(params.ants, colonyThreads(params));
  }

  // Stopped during an iteration's walks, that iteration is dropped: the run keeps the best
  // route of the iterations before it.
  ColonyRun run(const StopCheck& should_stop = {}, const IterationObserver& observer = {}) {
    ColonyRun run;
    should_stop_ = should_stop ? &should_stop : nullptr;
    int since_improvement = 0;
    for (int iteration = 1; iteration <= params_.max_iterations; ++iteration) {
      if (should_stop && should_stop(iteration - 1)) {
        run.interrupted = true;
        break;
      }
      rules_.transition.beginIteration(iteration, params_.max_iterations);
      const int walked = walkAnts(iteration);
      if (walk_stopped_.load(std::memory_order_relaxed)) {
        run.interrupted = true;
        break;
      }
      const bool improved = recordIteration(iteration, walked, run);
      rules_.update(field_, routes_, best_, worst_, run.best_cost);
      if (observer) observer(iteration, field_, setup_.region);
      since_improvement = improved ? 0 : since_improvement + 1;
      if (params_.early_stop_iterations > 0 && !run.best_cells.empty() &&
          (since_improvement >= params_.early_stop_iterations || run.best_cost <= good_enough_cost_)) {
        run.stopped_early = true;
        break;
      }
    }
    return run;
  }

 private:
  // The ants of one iteration; returns how many walked. With stop_gap in force (early stopping
  // on, the cheapest cost known) they walk in waves of kAntsPerWave, and the iteration ends
  // after the first wave that brings a route within the gap: the run stops there, and the rest
  // of the ants could not change that. Waves are fixed by ant index, not by thread, so the
  // result is the same on any thread count. Ants that did not walk count as neither complete
  // nor lost. Two: one ant per core on two cores; on long routes an ant walk takes
  // milliseconds, and the first ant within the gap usually comes in the first wave.
  static constexpr int kAntsPerWave = 2;
  int walkAnts(int iteration) {
    const int ants = params_.ants;
    const bool stop_gap_in_force = params_.early_stop_iterations > 0 && std::isfinite(good_enough_cost_);
    if (!stop_gap_in_force) {
      walkAnts(iteration, 0, ants);
      return ants;
    }
    for (int first = 0; first < ants; first += kAntsPerWave) {
      const int last = std::min(ants, first + kAntsPerWave);
      walkAnts(iteration, first, last);
      if (walk_stopped_.load(std::memory_order_relaxed)) return last;
      for (int k = first; k < last; ++k) {
        const AntRoute& route = routes_[static_cast<std::size_t>(k)];
        if (!route.complete || route.cost > good_enough_cost_) continue;
        for (int rest = last; rest < ants; ++rest) routes_[static_cast<std::size_t>(rest)].complete = false;
        return last;
      }
    }
    return ants;
  }

  // Ants first..last-1 of an iteration. They read the same pheromone and each has its own
  // random stream and route slot, so which worker walks which ant cannot change the result.
  void walkAnts(int iteration, int first, int last) {
    std::atomic<int> next_ant{first};
    const auto walk_claimed = [&](int worker) {
      AntWalker& walker = worker_state_[static_cast<std::size_t>(worker)].walker;
      AntRoute& scratch = worker_state_[static_cast<std::size_t>(worker)].scratch;
      StopPoll poll = should_stop_ != nullptr ? StopPoll(*should_stop_, iteration - 1) : StopPoll();
      for (int k = next_ant.fetch_add(1, std::memory_order_relaxed); k < last;
           k = next_ant.fetch_add(1, std::memory_order_relaxed)) {
        SplitMix64 rng = antStream(params_.seed, static_cast<std::uint64_t>(iteration), static_cast<std::uint64_t>(k));
        // Walk into the worker's own route, then swap it into the ant's slot: neighbouring
        // slots belong to other workers, and writing them step by step would share cache lines.
        walker.walk(setup_, rules_, rng, scratch, &poll);
        std::swap(scratch, routes_[static_cast<std::size_t>(k)]);
        if (poll.stopped()) {  // the iteration is dropped: leave the other ants unwalked
          walk_stopped_.store(true, std::memory_order_relaxed);
          next_ant.store(last, std::memory_order_relaxed);
          return;
        }
      }
    };
    if (on_workers_) workspace_.group().share(walk_claimed);
    else walk_claimed(0);
  }

  // Lost ants, this iteration's best and worst routes, the best so far, over the first `walked`
  // ants. Equally cheap routes: the lowest ant index, or with Rules::kFewerTurnsOnTies the one
  // with fewer turns first (it then replaces an equally cheap best so far, which keeps the
  // iteration that first found its cost).
  bool recordIteration(int iteration, int walked, ColonyRun& run) {
    constexpr double kTolerance = 1e-9;
    best_ = worst_ = -1;
    int lost = 0;
    for (int k = 0; k < walked; ++k) {
      const AntRoute& route = routes_[static_cast<std::size_t>(k)];
      if (!route.complete) {
        ++lost;
        continue;
      }
      if (best_ < 0 || route.cost < routes_[static_cast<std::size_t>(best_)].cost - kTolerance ||
          (Rules::kFewerTurnsOnTies && route.cost <= routes_[static_cast<std::size_t>(best_)].cost + kTolerance &&
           turnCount(route) < turnCount(routes_[static_cast<std::size_t>(best_)])))
        best_ = k;
      if (worst_ < 0 || route.cost > routes_[static_cast<std::size_t>(worst_)].cost + kTolerance) worst_ = k;
    }
    run.iterations_run = iteration;
    run.ants_per_iteration.push_back(walked);
    run.lost_ants_per_iteration.push_back(lost);
    bool improved = false;
    if (best_ >= 0) {
      const AntRoute& best = routes_[static_cast<std::size_t>(best_)];
      run.iteration_best_cost.push_back(best.cost);
      improved = best.cost < run.best_cost - kTolerance;
      const bool fewer_turns = Rules::kFewerTurnsOnTies && !improved && best.cost <= run.best_cost + kTolerance &&
                               turnCount(best) < best_turns_;
      if (improved || fewer_turns) {
        if (improved) {
          run.best_cost = best.cost;
          run.best_iteration = iteration;
        }
        run.best_cells.resize(best.cells.size());
        for (std::size_t k = 0; k < best.cells.size(); ++k) run.best_cells[k] = setup_.region.gridIndex(best.cells[k]);
        if (Rules::kFewerTurnsOnTies) best_turns_ = turnCount(best);
      }
    } else {
      run.iteration_best_cost.push_back(std::numeric_limits<double>::infinity());
    }
    run.best_cost_so_far.push_back(run.best_cost);
    return improved;
  }

  const WalkSetup& setup_;
  PheromoneField& field_;
  const ColonyParameters& params_;
  Rules rules_;
  double good_enough_cost_;  // stop_gap: a best route this cheap ends the run (early stopping on)
  ColonyWorkspace own_workspace_;  // used when the caller keeps none
  ColonyWorkspace& workspace_;
  std::vector<AntRoute>& routes_;
  std::vector<ColonyWorkspace::WorkerState>& worker_state_;
  bool on_workers_;  // walk on the worker threads (colonyWorkers > 1), else on the calling thread
  const StopCheck* should_stop_ = nullptr;  // run()'s, asked during the walks too
  std::atomic<bool> walk_stopped_{false};   // a walk was stopped: the iteration is dropped
  int best_ = -1;
  int worst_ = -1;
  int best_turns_ = 0;  // the best route so far's turns (Rules::kFewerTurnsOnTies)
};

}  // namespace eaci
