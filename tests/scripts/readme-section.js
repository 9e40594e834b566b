// Generated figures in README.md live between `<!-- NAME:start -->` and `<!-- NAME:end -->`
// markers, so the scripts that measure them (accuracy report, benchmark) keep them current.
import fs from 'node:fs';

export function replaceMarkedSection(file, name, content) {
  const start = `<!-- ${name}:start -->`;
  const end = `<!-- ${name}:end -->`;
  const text = fs.readFileSync(file, 'utf8');
  const from = text.indexOf(start);
  const to = text.indexOf(end);
  if (from < 0 || to < from) throw new Error(`${file} has no ${start} ... ${end} section to fill`);
  fs.writeFileSync(file, `${text.slice(0, from + start.length)}\n${content}\n${text.slice(to)}`);
}
