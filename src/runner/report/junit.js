// The test run as JUnit XML, the report format CI systems read (GitHub Actions' test reporters,
// GitLab, Jenkins): one <testcase> a shader, a <failure> with its reasons when it failed.

/** @param {string} text */
const escape = (text) =>
  text.replace(/[<>&"']/g, (c) => ({ '<': '&lt;', '>': '&gt;', '&': '&amp;', '"': '&quot;', "'": '&apos;' })[c] ?? c);

/**
 * @param {{name: string, ok: boolean, skipped?: boolean, failures: string[], notes: string[], ms: number}[]} results
 * @param {{seconds: number, renderer: string, date: string}} run date: the run's iDate at iTime 0
 */
export function junitXml(results, { seconds, renderer, date }) {
  const failures = results.filter((r) => !r.ok).length;
  const skipped = results.filter((r) => r.skipped).length;
  const cases = results.map((r) => {
    const open = `    <testcase classname="shaderproof" name="${escape(r.name)}" time="${(r.ms / 1000).toFixed(3)}"`;
    const out = r.notes.length ? `\n      <system-out>${escape(r.notes.join('\n'))}</system-out>` : '';
    if (r.skipped) return `${open}>\n      <skipped message="${escape(r.notes.join('; '))}"/>\n    </testcase>`;
    if (r.ok) return out ? `${open}>${out}\n    </testcase>` : `${open}/>`;
    const message = escape(r.failures[0] ?? 'failed');
    return `${open}>\n      <failure message="${message}">${escape(r.failures.join('\n'))}</failure>${out}\n    </testcase>`;
  });
  return `<?xml version="1.0" encoding="UTF-8"?>
<testsuites tests="${results.length}" failures="${failures}" time="${seconds.toFixed(3)}">
  <testsuite name="shaderproof" tests="${results.length}" failures="${failures}" skipped="${skipped}" time="${seconds.toFixed(3)}">
    <properties><property name="renderer" value="${escape(renderer)}"/><property name="iDate" value="${escape(date)}"/></properties>
${cases.join('\n')}
  </testsuite>
</testsuites>
`;
}
