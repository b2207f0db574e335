// The README's example is examples/readme_example.mjs, verbatim (from its first line to its
// last), and it runs and prints what the README says.
//
//   node --test test/

import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';

const example = fileURLToPath(new URL('../examples/readme_example.mjs', import.meta.url));
const readme = fileURLToPath(new URL('../README.md', import.meta.url));

test('README.md shows examples/readme_example.mjs verbatim', () => {
    const code = readFileSync(example, 'utf8');
    assert.ok(readFileSync(readme, 'utf8').includes('```js\n' + code + '```\n'),
        'README.md must contain the example between ```js fences; copy examples/readme_example.mjs into it');
});

test('the example prints the README numbers', () => {
    const output = execFileSync(process.execPath, [example], { encoding: 'utf8' });
    assert.equal(output, [
        "runner at { x: 2.5, y: 0, z: 4 }",
        '12 bounces, ends at z = 4.483 m',
        '140 points, first bounce at z = 9.70 m',
        '',
    ].join('\n'));
});
