// The command line's words for what node:util parseArgs refuses, and the one form it refuses that
// a person means plainly: a flag whose value starts with a dash (--time -1, --mouse -5,10).

/**
 * `--flag -value` as `--flag=-value` for a flag that takes a value, when the value reads as a
 * number or a list of them: parseArgs takes it for another flag ("argument is ambiguous"). A
 * negative number is then said to be out of range, in the flag's own words.
 * @param {string[]} argv
 * @param {Record<string, {type: string, short?: string}>} flags
 */
export function joinDashValues(argv, flags) {
  const takesValue = new Set(
    Object.entries(flags).flatMap(([name, { type, short }]) => (type === 'string' ? [`--${name}`, ...(short ? [`-${short}`] : [])] : [])),
  );
  const out = [];
  for (let i = 0; i < argv.length; i++) {
    const next = argv[i + 1];
    if (takesValue.has(argv[i]) && next !== undefined && /^-[\d.]/.test(next)) {
      out.push(`${argv[i]}=${next}`);
      i++;
    } else out.push(argv[i]);
  }
  return out;
}

/**
 * parseArgs's error in one line of the project's words.
 * @param {any} error
 */
export function argumentError(error) {
  const message = String(error?.message ?? error);
  const flag = /option '(?:-\w, )?(-{1,2}[\w-]+)/i.exec(message)?.[1] ?? '';
  switch (error?.code) {
    case 'ERR_PARSE_ARGS_UNKNOWN_OPTION':
      return `no flag ${flag || message}`;
    case 'ERR_PARSE_ARGS_INVALID_OPTION_VALUE':
      if (/does not take an argument/.test(message)) return `${flag} takes no value`;
      if (/ambiguous/.test(message)) return `${flag} needs a value (one that starts with "-" is written ${flag}=VALUE)`;
      return `${flag} needs a value`;
    case 'ERR_PARSE_ARGS_UNEXPECTED_POSITIONAL':
      return `unexpected ${/'([^']*)'/.exec(message)?.[1] ?? 'argument'}`;
    default:
      return message.split('\n')[0];
  }
}
