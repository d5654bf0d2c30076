// A real-client test (issue 14 "What must be shown" 2): drives `kerf lsp` with the protocol library
// VS Code's client is built on (vscode-languageserver-protocol over vscode-jsonrpc), on the sample
// workspace tests/editors/workspace, and prints what the server answered in a stable text form,
// which the CTest wrapper compares with tests/editors/node_client.expected (reviewed by hand).
//
//   node lsp_client.js KERF_BINARY WORKSPACE_DIR
'use strict';
const cp = require('child_process');
const fs = require('fs');
const path = require('path');
const { StreamMessageReader, StreamMessageWriter } = require('vscode-jsonrpc/node');
const proto = require('vscode-languageserver-protocol');

const [kerf, workspace] = process.argv.slice(2);
const uri = (name) => 'file://' + path.resolve(workspace, name).split('/').map(encodeURIComponent).join('/');
const mainUri = uri('main.nc');
const out = [];
const say = (line) => out.push(line);
const span = (r) => `${r.start.line}:${r.start.character}-${r.end.line}:${r.end.character}`;
const tail = (u) => decodeURIComponent(u.slice(u.lastIndexOf('/') + 1));

function timeout(ms, what) {
    // unref: a pending timeout must not keep the process alive once the test is done.
    return new Promise((_, reject) => setTimeout(() => reject(new Error(`timed out: ${what}`)), ms).unref());
}

async function main() {
    const server = cp.spawn(kerf, ['lsp'], { stdio: ['pipe', 'pipe', 'inherit'] });
    const exited = new Promise((resolve) => server.on('exit', (code) => resolve(code)));
    const connection = proto.createProtocolConnection(new StreamMessageReader(server.stdout), new StreamMessageWriter(server.stdin));
    const diagnostics = new Map();   // phase → params
    let indexed;
    const indexedDone = new Promise((resolve) => { indexed = resolve; });
    let completeSeen;
    const complete = new Promise((resolve) => { completeSeen = resolve; });
    connection.onNotification(proto.PublishDiagnosticsNotification.type, (p) => {
        if (p.uri !== mainUri) return;
        diagnostics.set(p.kerf.phase, p);
        if (p.kerf.phase === 'complete') completeSeen(p);
    });
    connection.onNotification(proto.LogMessageNotification.type, (m) => {
        if (m.message.startsWith('kerf lsp: indexed')) indexed();
    });
    connection.listen();

    const init = await connection.sendRequest(proto.InitializeRequest.type, {
        processId: process.pid, rootUri: uri('.').replace(/\/\.$/, ''), capabilities: {}, workspaceFolders: null,
    });
    say(`server: ${init.serverInfo.name} ${init.serverInfo.version}; sync ${init.capabilities.textDocumentSync.change}; ` +
        `encoding ${init.capabilities.positionEncoding}`);
    connection.sendNotification(proto.InitializedNotification.type, {});
    await Promise.race([indexedDone, timeout(30000, 'indexing')]);

    const text = fs.readFileSync(path.join(workspace, 'main.nc'), 'utf8');
    connection.sendNotification(proto.DidOpenTextDocumentNotification.type, {
        textDocument: { uri: mainUri, languageId: 'gcode', version: 1, text },
    });
    const final = await Promise.race([complete, timeout(30000, 'diagnostics')]);
    say(`static diagnostics first: ${diagnostics.has('static')}`);
    for (const d of final.diagnostics) say(`diagnostic ${span(d.range)} ${d.code} severity ${d.severity}: ${d.message.split('\n')[0]}`);

    const at = (line, character) => ({ textDocument: { uri: mainUri }, position: { line, character } });
    const hover = await connection.sendRequest(proto.HoverRequest.type, at(7, 5));
    say(`hover G71 ${span(hover.range)}: ${hover.contents.value.split('\n')[0]}`);
    const word = await connection.sendRequest(proto.HoverRequest.type, at(6, 9));
    say(`hover U1.: ${word.contents.value.split('\n')[0]}`);

    const def = await connection.sendRequest(proto.DefinitionRequest.type, at(12, 11));
    say(`definition p2000: ${tail(def.uri)} ${span(def.range)}`);
    const label = await connection.sendRequest(proto.DefinitionRequest.type, at(11, 10));
    say(`definition G70 P70: ${tail(label.uri)} ${span(label.range)}`);

    const refs = await connection.sendRequest(proto.ReferencesRequest.type, { ...at(8, 1), context: { includeDeclaration: true } });
    say(`references N70: ${refs.map((l) => `${tail(l.uri)} ${span(l.range)}`).join(', ')}`);

    const completion = await connection.sendRequest(proto.CompletionRequest.type, at(5, 5));
    const items = completion.items.filter((i) => i.label === 'G00' || i.label === 'G71 …');
    for (const i of items) say(`completion ${i.label}: ${i.detail}`);

    const tokens = await connection.sendRequest(proto.SemanticTokensRequest.type, { textDocument: { uri: mainUri } });
    const legend = init.capabilities.semanticTokensProvider.legend;
    let line = 0, col = 0;
    const decoded = [];
    for (let i = 0; i < tokens.data.length; i += 5) {
        line += tokens.data[i];
        col = tokens.data[i] ? tokens.data[i + 1] : col + tokens.data[i + 1];
        if (line === 7) decoded.push(`${col}+${tokens.data[i + 2]} ${legend.tokenTypes[tokens.data[i + 3]]}`);
    }
    say(`semantic tokens of line 7: ${decoded.join(', ')}`);

    const edits = await connection.sendRequest(proto.DocumentFormattingRequest.type, {
        textDocument: { uri: mainUri }, options: { tabSize: 4, insertSpaces: true },
    });
    for (const e of edits) say(`formatting ${span(e.range)} -> ${JSON.stringify(e.newText)}`);

    const rename = await connection.sendRequest(proto.RenameRequest.type, { ...at(1, 2), newName: '1001' });
    for (const [u, list] of Object.entries(rename.changes)) for (const e of list) say(`rename O1000: ${tail(u)} ${span(e.range)} -> ${e.newText}`);

    await connection.sendRequest(proto.ShutdownRequest.type);
    connection.sendNotification(proto.ExitNotification.type);
    const code = await Promise.race([exited, timeout(10000, 'exit')]);
    say(`exit code ${code}`);
    connection.dispose();
    process.stdout.write(out.join('\n') + '\n');
}

main().catch((e) => {
    process.stderr.write(`lsp_client.js: ${e.stack || e}\n`);
    process.exit(1);
});
