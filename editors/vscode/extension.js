// SPDX-License-Identifier: EPL-2.0
// Starts the RsaML language server (rsaml language-server) for .rsa files.
'use strict';
const vscode = require('vscode');
const { LanguageClient } = require('vscode-languageclient/node');

let client;

function activate(context) {
  const config = vscode.workspace.getConfiguration('rsaml');
  const serverOptions = {
    command: config.get('server.command', 'rsaml'),
    args: config.get('server.args', ['language-server'])
  };
  const clientOptions = {
    // untitled: a new document set to the RsaML language, checked before it is saved.
    documentSelector: [{ scheme: 'file', language: 'rsaml' }, { scheme: 'untitled', language: 'rsaml' }],
    synchronize: { fileEvents: vscode.workspace.createFileSystemWatcher('**/*.rsa') }
  };
  client = new LanguageClient('rsaml', 'RsaML', serverOptions, clientOptions);
  client.start();
  context.subscriptions.push({ dispose: () => client && client.stop() });
}

function deactivate() {
  return client ? client.stop() : undefined;
}

module.exports = { activate, deactivate };
