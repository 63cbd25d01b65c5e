//! The statecheck language server: the editor's view of a `.sc` file.
//!
//! This crate exists so that an editor gets what the command line gives — the checker's
//! diagnostics, the formatter — while the user types, plus navigation. It speaks the Language
//! Server Protocol over stdio ([`serve_stdio`], run by `statecheck lsp`) or over any
//! [`lsp_server::Connection`] ([`run`], used by the tests on in-memory channels). Like the CLI
//! it is an edge: it depends on `syntax` and `model`, never on an engine, and decides no
//! semantics. Capabilities: full-document sync with diagnostics on every change, hover (the
//! declaration with its type and range), go to definition, find references, rename,
//! completion (states, events, variables, constants, literals, functions), document symbols
//! (the state hierarchy as an outline), formatting, and quick fixes for the diagnostics whose
//! hint names a replacement (`did you mean `X`?`).

mod convert;
mod handlers;
mod imports;
pub mod index;

use lsp_server::{Connection, Message, Notification, Request, Response};
use lsp_types::notification::{
    DidChangeTextDocument, DidCloseTextDocument, DidOpenTextDocument, Notification as _,
    PublishDiagnostics,
};
use lsp_types::request::{
    CodeActionRequest, Completion, DocumentSymbolRequest, Formatting, GotoDefinition, HoverRequest,
    References, Rename, Request as _,
};
use lsp_types::{
    CodeActionProviderCapability, CompletionOptions, HoverProviderCapability, OneOf,
    PublishDiagnosticsParams, ServerCapabilities, TextDocumentSyncCapability, TextDocumentSyncKind,
    Uri,
};
use std::collections::BTreeMap;

/// Why the server stopped abnormally.
#[derive(Debug)]
pub struct Error {
    /// What went wrong.
    pub kind: ErrorKind,
}

/// The kinds of [`Error`].
#[derive(Debug)]
#[non_exhaustive]
pub enum ErrorKind {
    /// The client broke the protocol (or the connection closed during initialisation).
    Protocol(String),
}

impl std::fmt::Display for Error {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match &self.kind {
            ErrorKind::Protocol(m) => write!(f, "language server protocol error: {m}"),
        }
    }
}

impl std::error::Error for Error {}

fn protocol(e: impl std::fmt::Display) -> Error {
    Error {
        kind: ErrorKind::Protocol(e.to_string()),
    }
}

/// What the server announces.
pub fn capabilities() -> ServerCapabilities {
    ServerCapabilities {
        text_document_sync: Some(TextDocumentSyncCapability::Kind(TextDocumentSyncKind::FULL)),
        hover_provider: Some(HoverProviderCapability::Simple(true)),
        definition_provider: Some(OneOf::Left(true)),
        references_provider: Some(OneOf::Left(true)),
        rename_provider: Some(OneOf::Left(true)),
        completion_provider: Some(CompletionOptions {
            trigger_characters: Some(vec![".".to_string()]),
            ..CompletionOptions::default()
        }),
        document_symbol_provider: Some(OneOf::Left(true)),
        document_formatting_provider: Some(OneOf::Left(true)),
        code_action_provider: Some(CodeActionProviderCapability::Simple(true)),
        ..ServerCapabilities::default()
    }
}

/// Serve on standard input and output until the client says `exit`.
pub fn serve_stdio() -> Result<(), Error> {
    let (conn, io) = Connection::stdio();
    run(&conn)?;
    drop(conn);
    io.join().map_err(protocol)
}

/// Initialise, then serve requests and notifications on `conn` until `shutdown`/`exit`.
pub fn run(conn: &Connection) -> Result<(), Error> {
    let caps = serde_json::to_value(capabilities()).map_err(protocol)?;
    conn.initialize(caps).map_err(protocol)?;
    let mut docs: BTreeMap<String, (Uri, String)> = BTreeMap::new();
    for msg in &conn.receiver {
        match msg {
            Message::Request(req) => {
                if conn.handle_shutdown(&req).map_err(protocol)? {
                    return Ok(());
                }
                let resp = respond(&docs, req);
                conn.sender
                    .send(Message::Response(resp))
                    .map_err(protocol)?;
            }
            Message::Notification(n) => {
                if let Some(uri) = update(&mut docs, n) {
                    publish(conn, &docs, &uri)?;
                }
            }
            Message::Response(_) => {}
        }
    }
    Ok(())
}

/// Apply a document notification; returns the document whose diagnostics to publish.
fn update(docs: &mut BTreeMap<String, (Uri, String)>, n: Notification) -> Option<Uri> {
    match n.method.as_str() {
        DidOpenTextDocument::METHOD => {
            let p: lsp_types::DidOpenTextDocumentParams = serde_json::from_value(n.params).ok()?;
            let uri = p.text_document.uri;
            docs.insert(
                uri.as_str().to_string(),
                (uri.clone(), p.text_document.text),
            );
            Some(uri)
        }
        DidChangeTextDocument::METHOD => {
            let p: lsp_types::DidChangeTextDocumentParams =
                serde_json::from_value(n.params).ok()?;
            let uri = p.text_document.uri;
            // Full sync: the last change holds the whole text.
            let text = p.content_changes.into_iter().last()?.text;
            docs.insert(uri.as_str().to_string(), (uri.clone(), text));
            Some(uri)
        }
        DidCloseTextDocument::METHOD => {
            let p: lsp_types::DidCloseTextDocumentParams = serde_json::from_value(n.params).ok()?;
            docs.remove(p.text_document.uri.as_str());
            None
        }
        _ => None,
    }
}

fn publish(
    conn: &Connection,
    docs: &BTreeMap<String, (Uri, String)>,
    uri: &Uri,
) -> Result<(), Error> {
    let Some((_, text)) = docs.get(uri.as_str()) else {
        return Ok(());
    };
    let params = PublishDiagnosticsParams {
        uri: uri.clone(),
        diagnostics: handlers::diagnostics(uri, text),
        version: None,
    };
    let n = Notification::new(PublishDiagnostics::METHOD.to_string(), params);
    conn.sender.send(Message::Notification(n)).map_err(protocol)
}

/// Answer one request (an unknown method or bad parameters get an error response).
fn respond(docs: &BTreeMap<String, (Uri, String)>, req: Request) -> Response {
    let id = req.id.clone();
    let result = match req.method.as_str() {
        HoverRequest::METHOD => handle::<HoverRequest>(docs, req, handlers::hover),
        GotoDefinition::METHOD => handle::<GotoDefinition>(docs, req, handlers::definition),
        References::METHOD => handle::<References>(docs, req, handlers::references),
        Rename::METHOD => handle::<Rename>(docs, req, handlers::rename),
        Completion::METHOD => handle::<Completion>(docs, req, handlers::completion),
        DocumentSymbolRequest::METHOD => {
            handle::<DocumentSymbolRequest>(docs, req, handlers::symbols)
        }
        Formatting::METHOD => handle::<Formatting>(docs, req, handlers::formatting),
        CodeActionRequest::METHOD => handle::<CodeActionRequest>(docs, req, handlers::code_actions),
        m => Err((
            lsp_server::ErrorCode::MethodNotFound as i32,
            format!("unsupported method `{m}`"),
        )),
    };
    match result {
        Ok(v) => Response::new_ok(id, v),
        Err((code, msg)) => Response::new_err(id, code, msg),
    }
}

/// The document a request is about.
pub(crate) struct Doc<'a> {
    pub uri: &'a Uri,
    pub text: &'a str,
}

type Handled = Result<serde_json::Value, (i32, String)>;

fn handle<R>(
    docs: &BTreeMap<String, (Uri, String)>,
    req: Request,
    f: fn(&Doc<'_>, R::Params) -> R::Result,
) -> Handled
where
    R: lsp_types::request::Request,
    R::Params: handlers::HasUri,
{
    let params: R::Params = serde_json::from_value(req.params)
        .map_err(|e| (lsp_server::ErrorCode::InvalidParams as i32, e.to_string()))?;
    let key = handlers::HasUri::uri(&params).as_str().to_string();
    let Some((uri, text)) = docs.get(&key) else {
        return Err((
            lsp_server::ErrorCode::InvalidParams as i32,
            format!("document `{key}` is not open"),
        ));
    };
    let doc = Doc { uri, text };
    serde_json::to_value(f(&doc, params))
        .map_err(|e| (lsp_server::ErrorCode::InternalError as i32, e.to_string()))
}
