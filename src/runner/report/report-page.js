// The HTML report's own style and script (html-report.js writes them into index.html): no file
// beside them, no font, no request, so that the page opens from file:// offline, in Chromium and
// Firefox alike. The script only adds what a static page cannot do: the reference / actual
// comparison's mode (a slider, or either whole), the filter, expand and collapse all. The images'
// zoom, pan and pixel readout are viewer-page.js's.

export const REPORT_STYLE = `
:root { color-scheme: light dark; --fail: #c62828; --pass: #2e7d32; --skip: #757575; --line: #8884; --soft: #8881; }
* { box-sizing: border-box; }
body { margin: 0; font: 14px/1.45 system-ui, sans-serif; }
header, main { max-width: 1400px; margin: 0 auto; padding: 12px 20px; }
h1 { font-size: 20px; margin: 8px 0; }
h1 code, summary code { font-size: 14px; }
h2 { font-size: 16px; margin: 20px 0 8px; }
.verdict { font-size: 16px; font-weight: 600; margin: 4px 0 8px; }
.verdict.fail { color: var(--fail); }
.verdict.pass { color: var(--pass); }
dl { display: grid; grid-template-columns: max-content 1fr; gap: 2px 12px; margin: 8px 0; }
dt { color: var(--skip); }
dd { margin: 0; overflow-wrap: anywhere; }
nav { display: flex; flex-wrap: wrap; gap: 6px; align-items: center; margin-top: 8px; }
button { font: inherit; padding: 2px 10px; border: 1px solid var(--line); border-radius: 4px; background: var(--soft); color: inherit; cursor: pointer; }
button[aria-pressed="true"] { background: #1565c0; border-color: #1565c0; color: #fff; }
.case { border: 1px solid var(--line); border-left: 4px solid var(--skip); border-radius: 4px; margin: 6px 0; }
.case.fail { border-left-color: var(--fail); }
.case.pass { border-left-color: var(--pass); }
summary { display: flex; gap: 10px; align-items: center; padding: 6px 10px; cursor: pointer; flex-wrap: wrap; }
summary .reason { flex: 1 1 300px; color: var(--fail); overflow: hidden; text-overflow: ellipsis; white-space: nowrap; min-width: 0; }
summary .skip .reason, .skip summary .reason { color: var(--skip); }
summary .ms { margin-left: auto; color: var(--skip); font-variant-numeric: tabular-nums; }
.badge { font-weight: 700; font-size: 12px; text-transform: uppercase; }
.fail .badge { color: var(--fail); }
.pass .badge { color: var(--pass); }
.skip .badge { color: var(--skip); }
.thumb { display: block; max-width: 160px; max-height: 90px; width: auto; height: auto; background: var(--soft); }
.body { padding: 4px 12px 12px; }
.failures { margin: 4px 0; padding-left: 18px; color: var(--fail); white-space: pre-wrap; overflow-wrap: anywhere; }
.facts, .notes, .missing { margin: 4px 0; padding-left: 18px; }
.missing .unallowed { color: var(--fail); }
.source { font: 12px/1.5 ui-monospace, monospace; margin: 6px 0; padding: 6px 0; background: var(--soft); overflow: auto; }
.source div { white-space: pre; padding: 0 10px; }
.source .n { display: inline-block; min-width: 4ch; text-align: right; margin-right: 12px; color: var(--skip); user-select: none; }
.source .error { background: #c6282822; }
.source .message { white-space: pre-wrap; color: var(--fail); padding-left: calc(4ch + 22px); }
.sound table { border-collapse: collapse; margin: 6px 0; }
.sound td, .sound th { border: 1px solid var(--line); padding: 2px 10px; text-align: right; }
.sound th:first-child, .sound td:first-child { text-align: left; }
.sound .over { color: var(--fail); font-weight: 700; }
.sound p { display: flex; align-items: center; gap: 8px; margin: 4px 0; }
.sound p audio { height: 32px; }
.sound svg { display: block; max-width: 100%; margin: 6px 0; }
.sound svg text { font-size: 10px; fill: currentColor; }
body[data-filter="failed"] .case:not(.fail), body[data-filter="passed"] .case:not(.pass), body[data-filter="skipped"] .case:not(.skip) { display: none; }
body[data-filter="failed"] section:not(#failed), body[data-filter="passed"] section:not(#passed), body[data-filter="skipped"] section:not(#skipped) { display: none; }
`;

/** The page's script: written into index.html as `(source)()`. It runs in the report's page. */
export function reportScript() {
  /** @param {Element} group @param {Element} chosen */
  const press = (group, chosen) => {
    for (const button of group.querySelectorAll('button')) button.setAttribute('aria-pressed', String(button === chosen));
  };
  document.addEventListener('click', (event) => {
    const button = /** @type {HTMLElement | null} */ (/** @type {Element} */ (event.target).closest('button'));
    if (!button) return;
    const group = /** @type {Element} */ (button.parentElement);
    if (button.dataset.mode) {
      const compare = /** @type {HTMLElement | null} */ (button.closest('.body')?.querySelector('.compare') ?? null);
      if (compare) compare.dataset.mode = button.dataset.mode;
      press(group, button);
    } else if (button.dataset.filter) {
      document.body.dataset.filter = button.dataset.filter;
      press(group, button);
    } else if (button.dataset.open) {
      for (const details of document.querySelectorAll('details.case'))
        /** @type {HTMLDetailsElement} */ (details).open = button.dataset.open === 'all';
    }
  });
}
