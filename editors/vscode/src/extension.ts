// Starts the KSE language server (`kse lsp`, over stdio) for formula files and statecharts.
import * as vscode from 'vscode';
import { LanguageClient, LanguageClientOptions, ServerOptions } from 'vscode-languageclient/node';

let client: LanguageClient | undefined;

export async function activate(context: vscode.ExtensionContext): Promise<void> {
  const command = vscode.workspace.getConfiguration('kse').get<string>('path') || 'kse';
  // no transport option: the client then adds no --stdio, and kse lsp speaks on stdio anyway
  const server: ServerOptions = { command, args: ['lsp'] };
  const options: LanguageClientOptions = {
    documentSelector: [
      { scheme: 'file', language: 'liveness' },
      { scheme: 'untitled', language: 'liveness' },
      { scheme: 'file', language: 'kse-statechart' },
    ],
  };
  client = new LanguageClient('kse', 'KSE language server', server, options);
  context.subscriptions.push(
    vscode.workspace.onDidChangeConfiguration(async (event) => {
      if (event.affectsConfiguration('kse.path') && client) {
        await client.stop();
        client = new LanguageClient('kse', 'KSE language server', { command: vscode.workspace.getConfiguration('kse').get<string>('path') || 'kse', args: ['lsp'] }, options);
        await start(client);
      }
    }),
  );
  await start(client);
}

async function start(languageClient: LanguageClient): Promise<void> {
  try {
    await languageClient.start();
  } catch (error) {
    const command = vscode.workspace.getConfiguration('kse').get<string>('path') || 'kse';
    void vscode.window.showErrorMessage(
      `KSE: cannot start the language server with '${command} lsp' (${String(error)}). Set kse.path to the kse command.`,
    );
  }
}

export async function deactivate(): Promise<void> {
  if (client) {
    await client.stop();
  }
}
