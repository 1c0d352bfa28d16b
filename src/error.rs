//! Why a solve could not run. What a solve found is a [`crate::Status`].

use std::path::PathBuf;

/// Every error names the item and the field at fault, so that a user can
/// find the bad number in a file of thousands.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// A value failed a check: `item` is e.g. "scene 0, contact 3", `field` e.g. "normal".
    #[error("{item}: field `{field}`: {reason}")]
    Invalid {
        /// The item at fault, e.g. "scene 0, contact 3" or "problem 4".
        item: String,
        /// The field at fault, e.g. `normal` or `M[0][1]`.
        field: String,
        /// What is wrong with it.
        reason: String,
    },
    /// The JSON text could not be parsed into the expected shape.
    #[error("{path}: malformed JSON at line {line}, column {column}: {message}")]
    Json {
        /// The file.
        path: String,
        /// 1-based line of the fault.
        line: usize,
        /// 1-based column of the fault.
        column: usize,
        /// The parser's message.
        message: String,
    },
    /// A Siconos .dat file could not be parsed.
    #[error("{path}: malformed .dat file: {message}")]
    Dat {
        /// The file.
        path: String,
        /// What is wrong, with the line where it is known.
        message: String,
    },
    /// Reading or writing a file failed.
    #[error("{path}: {source}")]
    Io {
        /// The file.
        path: PathBuf,
        /// The operating system's error.
        #[source]
        source: std::io::Error,
    },
    /// A request the chosen solver cannot serve (for example enumeration of
    /// a problem too large to enumerate).
    #[error("{0}")]
    Unsupported(String),
    /// The GPU could not be used.
    #[error("GPU: {0}")]
    Gpu(String),
}

impl Error {
    /// Shorthand for [`Error::Invalid`]. `item` is anything that displays
    /// as the item's name (a `&str`, or `format_args!("scene {i}")`, which
    /// is rendered only here, when a check has failed).
    pub fn invalid(
        item: impl std::fmt::Display,
        field: impl Into<String>,
        reason: impl Into<String>,
    ) -> Self {
        Error::Invalid {
            item: item.to_string(),
            field: field.into(),
            reason: reason.into(),
        }
    }

    /// Converts a serde_json error, keeping its position (once: serde's
    /// message without its own " at line L column C", which the error's
    /// text states already).
    pub fn json(path: impl Into<String>, e: serde_json::Error) -> Self {
        let (line, column) = (e.line(), e.column());
        let text = e.to_string();
        let message = text
            .strip_suffix(&format!(" at line {line} column {column}"))
            .unwrap_or(&text)
            .to_string();
        Error::Json {
            path: path.into(),
            line,
            column,
            message,
        }
    }
}
