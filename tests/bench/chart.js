// The benchmark's chart: one point per variant, time (x, log) against RMSE (y, log), the Pareto
// front (no other variant is both faster and more accurate) drawn as a line. Plain SVG text.

/** Variants that no other variant beats on both time and error, fastest first. */
export function paretoFront(results) {
  const sorted = [...results].sort((a, b) => a.medianMs - b.medianMs || a.rmse - b.rmse);
  const front = [];
  for (const r of sorted) if (!front.length || r.rmse < front[front.length - 1].rmse) front.push(r);
  return front;
}

// one per group (12 with the standalone peer), so that no two series share a colour
const COLORS = [
  '#555555',
  '#1f77b4',
  '#2ca02c',
  '#9467bd',
  '#d62728',
  '#ff7f0e',
  '#8c564b',
  '#e377c2',
  '#bcbd22',
  '#17becf',
  '#393b79',
  '#e7ba52',
];
const escape = (s) => s.replace(/&/g, '&amp;').replace(/</g, '&lt;');

/**
 * @param {Array<{name: string, group: string, medianMs: number, rmse: number}>} results
 * @param {{title?: string, width?: number, height?: number}} [options]
 * @returns {string} the SVG
 */
export function chartSvg(results, { title, width = 760, height = 460 } = {}) {
  const margin = { left: 70, right: 210, top: 40, bottom: 50 };
  const plotW = width - margin.left - margin.right;
  const plotH = height - margin.top - margin.bottom;
  const log = Math.log10;
  const xs = results.map((r) => log(r.medianMs));
  const ys = results.map((r) => log(r.rmse));
  const [x0, x1] = [Math.floor(Math.min(...xs) * 2) / 2, Math.ceil(Math.max(...xs) * 2) / 2];
  const [y0, y1] = [Math.floor(Math.min(...ys) * 2) / 2, Math.ceil(Math.max(...ys) * 2) / 2];
  const px = (ms) => margin.left + ((log(ms) - x0) / (x1 - x0 || 1)) * plotW;
  const py = (e) => margin.top + plotH - ((log(e) - y0) / (y1 - y0 || 1)) * plotH;
  const groups = [...new Set(results.map((r) => r.group))];
  const color = (g) => COLORS[groups.indexOf(g) % COLORS.length];
  const parts = [
    `<svg xmlns="http://www.w3.org/2000/svg" width="${width}" height="${height}" viewBox="0 0 ${width} ${height}" font-family="sans-serif" font-size="11">`,
    `<rect width="${width}" height="${height}" fill="white"/>`,
    `<text x="${margin.left}" y="22" font-size="14">${escape(title ?? '')}</text>`,
  ];
  // Log-scale grid lines at 1, 2 and 5 times each power of ten inside [lo, hi] (log10 units).
  const ticks = (lo, hi) => {
    const values = [];
    for (let e = Math.floor(lo); e <= Math.ceil(hi); e++)
      for (const m of [1, 2, 5]) if (log(m * 10 ** e) >= lo && log(m * 10 ** e) <= hi) values.push(m * 10 ** e);
    return values;
  };
  for (const v of ticks(x0, x1)) {
    parts.push(`<line x1="${px(v)}" x2="${px(v)}" y1="${margin.top}" y2="${margin.top + plotH}" stroke="#eee"/>`);
    parts.push(`<text x="${px(v)}" y="${margin.top + plotH + 16}" text-anchor="middle">${v}</text>`);
  }
  for (const v of ticks(y0, y1)) {
    parts.push(`<line x1="${margin.left}" x2="${margin.left + plotW}" y1="${py(v)}" y2="${py(v)}" stroke="#eee"/>`);
    parts.push(`<text x="${margin.left - 6}" y="${py(v) + 4}" text-anchor="end">${v}</text>`);
  }
  parts.push(`<rect x="${margin.left}" y="${margin.top}" width="${plotW}" height="${plotH}" fill="none" stroke="#999"/>`);
  parts.push(`<text x="${margin.left + plotW / 2}" y="${height - 12}" text-anchor="middle">median frame time, ms (log)</text>`);
  parts.push(
    `<text transform="translate(16 ${margin.top + plotH / 2}) rotate(-90)" text-anchor="middle">RMSE against converged float64 (log)</text>`,
  );
  const front = paretoFront(results);
  parts.push(
    `<polyline fill="none" stroke="#000" stroke-dasharray="4 3" points="${front.map((r) => `${px(r.medianMs)},${py(r.rmse)}`).join(' ')}"/>`,
  );
  for (const r of results) {
    parts.push(
      `<circle cx="${px(r.medianMs)}" cy="${py(r.rmse)}" r="4" fill="${color(r.group)}"><title>${escape(r.name)}: ${r.medianMs.toFixed(1)} ms, RMSE ${r.rmse.toFixed(4)}</title></circle>`,
    );
    parts.push(
      `<text x="${px(r.medianMs) + 6}" y="${py(r.rmse) - 5}" fill="${color(r.group)}" font-size="9">${escape(r.name.replace(/ \(peer \d\)/, ''))}</text>`,
    );
  }
  groups.forEach((g, i) => {
    const y = margin.top + 10 + i * 16;
    parts.push(
      `<circle cx="${margin.left + plotW + 16}" cy="${y}" r="4" fill="${color(g)}"/><text x="${margin.left + plotW + 26}" y="${y + 4}">${escape(g)}</text>`,
    );
  });
  const y = margin.top + 10 + groups.length * 16;
  parts.push(
    `<line x1="${margin.left + plotW + 10}" x2="${margin.left + plotW + 22}" y1="${y}" y2="${y}" stroke="#000" stroke-dasharray="4 3"/><text x="${margin.left + plotW + 26}" y="${y + 4}">Pareto front</text>`,
  );
  parts.push('</svg>');
  return parts.join('\n') + '\n';
}
