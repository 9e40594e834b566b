// The speed targets, checked against one benchmark run at one size (1 sample per pixel,
// the default view): figures, not timed tests. Each returns whether it is met and a sentence.

const by = (results, name) => {
  const r = results.find((x) => x.name === name);
  if (!r) throw new Error(`benchmark: no result for "${name}"`);
  return r;
};
const x = (a, b) => `${(a / b).toFixed(2)}×`;

export function evaluateTargets(results) {
  const ours = by(results, 'project, 1 spp');
  const targets = [];

  // 1. At least 3x faster than sphere tracing, at equal or lower error: against the cheapest
  //    sphere-tracing variant that is at least as accurate as ours, or else the most accurate.
  const tracers = results.filter((r) => r.group === 'peer: sphere tracing').sort((a, b) => a.medianMs - b.medianMs);
  const rival = tracers.find((r) => r.rmse <= ours.rmse) ?? [...tracers].sort((a, b) => a.rmse - b.rmse)[0];
  const speedup = rival.medianMs / ours.medianMs;
  targets.push({
    met: speedup >= 3 && ours.rmse <= rival.rmse,
    text: `${x(rival.medianMs, ours.medianMs)} faster than ${rival.name} (${rival.medianMs.toFixed(1)} ms, RMSE ${rival.rmse.toFixed(4)}) with RMSE ${ours.rmse.toFixed(4)} (target: 3× at equal or lower error)`,
  });

  // 2. At least 1.6x faster than the same shader with the savings off, at the same error.
  const off = by(results, 'project, savings off');
  targets.push({
    met: off.medianMs / ours.medianMs >= 1.6 && Math.abs(off.rmse - ours.rmse) <= 1e-4,
    text: `${x(off.medianMs, ours.medianMs)} faster than with the savings off (${off.medianMs.toFixed(1)} ms), RMSE ${ours.rmse.toFixed(4)} vs ${off.rmse.toFixed(4)} (target: 1.6× at the same error)`,
  });

  // 3. Shadows and reflections together cost at most 50% more than primary rays alone.
  const primary = by(results, 'project, primary rays only');
  const floor = by(results, 'empty shader (floor)');
  targets.push({
    met: ours.medianMs <= 1.5 * primary.medianMs,
    text: `shadows and reflections add ${(100 * (ours.medianMs / primary.medianMs - 1)).toFixed(0)}% to primary rays alone (${primary.medianMs.toFixed(1)} → ${ours.medianMs.toFixed(1)} ms; ${(100 * ((ours.medianMs - floor.medianMs) / (primary.medianMs - floor.medianMs) - 1)).toFixed(0)}% above the empty-shader floor) (target: at most 50%)`,
  });

  // 4. At least 10x lower RMSE than the assignment's algorithm, in no more than its time.
  const assignment = by(results, 'assignment (peer 1)');
  targets.push({
    met: assignment.rmse / ours.rmse >= 10 && ours.medianMs <= assignment.medianMs,
    text: `RMSE ${x(assignment.rmse, ours.rmse)} lower than the assignment's (${assignment.rmse.toFixed(4)}), in ${x(ours.medianMs, assignment.medianMs)} its time (${assignment.medianMs.toFixed(1)} ms) (target: 10× lower, no slower)`,
  });
  return targets;
}
