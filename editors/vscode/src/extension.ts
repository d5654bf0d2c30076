// The kerf extension: starts `kerf lsp` (kerf.path) for G-code files and passes the kerf.*
// settings; everything else (diagnostics, hover, completion, navigation, formatting, hints) is the
// server's. Highlighting before the server runs comes from syntaxes/gcode.tmLanguage.json.
import * as vscode from 'vscode';
import { LanguageClient, LanguageClientOptions, ServerOptions, TransportKind } from 'vscode-languageclient/node';

let client: LanguageClient | undefined;

function settings(): Record<string, string> {
    const c = vscode.workspace.getConfiguration('kerf');
    return {
        dialect: c.get<string>('dialect', 'auto'),
        machine: c.get<string>('machine', ''),
        language: c.get<string>('language', 'en'),
        baseline: c.get<string>('baseline', ''),
    };
}

export async function activate(context: vscode.ExtensionContext): Promise<void> {
    const command = vscode.workspace.getConfiguration('kerf').get<string>('path', 'kerf');
    const serverOptions: ServerOptions = {
        run: { command, args: ['lsp'], transport: TransportKind.stdio },
        debug: { command, args: ['lsp', '--log', context.logUri.fsPath + '.log'], transport: TransportKind.stdio },
    };
    const clientOptions: LanguageClientOptions = {
        documentSelector: [{ scheme: 'file', language: 'gcode' }, { scheme: 'untitled', language: 'gcode' }],
        initializationOptions: settings(),
        synchronize: { configurationSection: 'kerf' },
    };
    client = new LanguageClient('kerf', 'kerf', serverOptions, clientOptions);
    context.subscriptions.push(
        vscode.workspace.onDidChangeConfiguration(async (e) => {
            if (e.affectsConfiguration('kerf.path') && client) {
                await client.stop();
                await client.start();
            }
        }),
    );
    await client.start();
}

export async function deactivate(): Promise<void> {
    if (client) await client.stop();
}
