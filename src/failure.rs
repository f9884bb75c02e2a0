//! [`Failure`]: how every command fails, with what to tell the user and the exit code.

use topolab_structures::Error;

/// A failed command: what to tell the user and the exit code.
#[derive(Debug)]
pub struct Failure {
    /// The message, with context.
    pub message: String,
    /// The exit code.
    pub code: u8,
}

impl Failure {
    /// An input that cannot be read as a mesh (exit code 2).
    pub fn unreadable(what: &str, e: &Error) -> Self {
        Self {
            message: format!("cannot read {what}: {e}"),
            code: 2,
        }
    }
    /// A usage error (exit code 2).
    pub fn usage(message: String) -> Self {
        Self { message, code: 2 }
    }
}
