// Tokenizes sample programs with the extension's TextMate grammar, through vscode-textmate and
// vscode-oniguruma as VS Code does, and prints one line per token: "line:col 'text' scope scope…"
// (the scopes after source.gcode). The CTest wrapper compares it with tests/editors/tokens/*.tokens.
//
//   node tokenize.js SAMPLE.nc
'use strict';
const fs = require('fs');
const path = require('path');
const vsctm = require('vscode-textmate');
const oniguruma = require('vscode-oniguruma');

async function main() {
    const wasm = fs.readFileSync(require.resolve('vscode-oniguruma/release/onig.wasm')).buffer;
    await oniguruma.loadWASM(wasm);
    const registry = new vsctm.Registry({
        onigLib: Promise.resolve({
            createOnigScanner: (patterns) => new oniguruma.OnigScanner(patterns),
            createOnigString: (s) => new oniguruma.OnigString(s),
        }),
        loadGrammar: async (scope) => {
            if (scope !== 'source.gcode') return null;
            const file = path.join(__dirname, '..', 'syntaxes', 'gcode.tmLanguage.json');
            return vsctm.parseRawGrammar(fs.readFileSync(file, 'utf8'), file);
        },
    });
    const grammar = await registry.loadGrammar('source.gcode');
    const lines = fs.readFileSync(process.argv[2], 'utf8').split(/\r?\n/);
    let state = vsctm.INITIAL;
    const out = [];
    lines.forEach((line, n) => {
        const result = grammar.tokenizeLine(line, state);
        for (const t of result.tokens) {
            const text = line.slice(t.startIndex, t.endIndex);
            if (text.trim() === '') continue;
            out.push(`${n}:${t.startIndex} '${text}' ${t.scopes.slice(1).join(' ') || '-'}`);
        }
        state = result.ruleStack;
    });
    process.stdout.write(out.join('\n') + '\n');
}

main().catch((e) => {
    process.stderr.write(`tokenize.js: ${e.stack || e}\n`);
    process.exit(1);
});
