#!/usr/bin/env node
// The command line's entry point (package.json "bin"): src/cli/main.js does the work.
import { main } from '../src/cli/main.js';

main(process.argv.slice(2)).then(
  (code) => (process.exitCode = code),
  (error) => {
    console.error(error?.stack ?? error);
    process.exitCode = 1;
  },
);
