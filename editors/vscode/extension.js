// The client: starts `statecheck lsp` and connects VS Code to it over stdio.
const vscode = require("vscode");
const { LanguageClient, TransportKind } = require("vscode-languageclient/node");

let client;

function activate(context) {
  const command = vscode.workspace.getConfiguration("statecheck").get("path") || "statecheck";
  const server = { command, args: ["lsp"], transport: TransportKind.stdio };
  client = new LanguageClient(
    "statecheck",
    "statecheck",
    { run: server, debug: server },
    { documentSelector: [{ scheme: "file", language: "statecheck" }] }
  );
  context.subscriptions.push(client);
  return client.start();
}

function deactivate() {
  return client ? client.stop() : undefined;
}

module.exports = { activate, deactivate };
