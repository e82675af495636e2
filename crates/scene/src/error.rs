//! Input errors that name the file and the problem.

use std::fmt;
use std::path::{Path, PathBuf};

/// A problem with an input file: which file, and what is wrong with it.
#[derive(Debug)]
pub struct Error {
    /// The file at fault, when the error came from one.
    pub path: Option<PathBuf>,
    /// What is wrong, in words a user can act on.
    pub message: String,
}

pub type Result<T> = std::result::Result<T, Error>;

impl Error {
    /// Invalid content (the caller adds the file with [`Error::in_file`]).
    pub fn invalid(message: impl Into<String>) -> Self {
        Error { path: None, message: message.into() }
    }

    /// A file that could not be read or written.
    pub fn io(path: &Path, e: std::io::Error) -> Self {
        let what = match e.kind() {
            std::io::ErrorKind::NotFound => "no such file".to_string(),
            std::io::ErrorKind::PermissionDenied => "permission denied".to_string(),
            _ => e.to_string(),
        };
        Error { path: Some(path.to_path_buf()), message: what }
    }

    /// Attaches the file the error came from, unless one is already named.
    pub fn in_file(mut self, path: &Path) -> Self {
        if self.path.is_none() {
            self.path = Some(path.to_path_buf());
        }
        self
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.path {
            Some(p) => write!(f, "{}: {}", p.display(), self.message),
            None => f.write_str(&self.message),
        }
    }
}

impl std::error::Error for Error {}

/// Parses JSON, turning serde's message into one that says where and, for the
/// non-JSON tokens people write for non-finite numbers, why.
pub fn parse_json<T: serde::de::DeserializeOwned>(text: &str) -> Result<T> {
    serde_json::from_str(text).map_err(|e| {
        let (line, col) = (e.line(), e.column());
        let near = text.lines().nth(line.saturating_sub(1)).unwrap_or("");
        let start = col.saturating_sub(1).min(near.len());
        let tail = near.get(start..).unwrap_or("");
        let full = e.to_string();
        let msg = full.strip_suffix(&format!(" at line {line} column {col}")).unwrap_or(&full);
        let hint = ["NaN", "Infinity", "-Infinity", "inf", "nan"]
            .iter()
            .find(|t| tail.starts_with(**t))
            .map(|t| format!(" ({t} is not a number: coordinates must be finite)"))
            .or_else(|| msg.contains("number out of range").then(|| " (numbers must be finite)".to_string()))
            .unwrap_or_default();
        let what = match e.classify() {
            serde_json::error::Category::Data => format!("{msg} at line {line} column {col}"),
            _ => format!("malformed JSON at line {line} column {col}: {msg}"),
        };
        Error::invalid(format!("{what}{hint}"))
    })
}
