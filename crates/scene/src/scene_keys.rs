//! Where a scene's values are: the file's text turns toml's spans into
//! line numbers ([`SceneFile`]), and the checks of one table's values
//! ([`Keys`]) name the line and the key in their errors.

use std::ops::Range;
use std::path::Path;

use glam::DVec3;
use toml::Spanned;

use crate::error::{KeyProblem, SceneError, one_line};
use crate::numbers::Shortest;

/// The scene's path and text: turns spans into line numbers for errors.
#[derive(Debug, Clone, Copy)]
pub struct SceneFile<'a> {
    /// The path as given on the command line.
    pub path: &'a Path,
    /// The whole text.
    pub text: &'a str,
}

impl SceneFile<'_> {
    /// The 1-based line holding byte `offset`.
    pub fn line_of(&self, offset: usize) -> u64 {
        let end = offset.min(self.text.len());
        1 + self.text.as_bytes()[..end]
            .iter()
            .filter(|&&b| b == b'\n')
            .count() as u64
    }

    /// An error at the start of `span` (`None`: the file as a whole).
    pub fn error(&self, span: Option<Range<usize>>, message: &str) -> SceneError {
        SceneError::Scene {
            path: self.path.to_owned(),
            line: span.map(|s| self.line_of(s.start)),
            message: one_line(message),
        }
    }
}

/// Checks of the values of one table, each error prefixed with its context
/// (`body `handle`: `).
#[derive(Debug, Clone)]
pub struct Keys<'a> {
    file: SceneFile<'a>,
    prefix: String,
    body: String,
}

impl<'a> Keys<'a> {
    /// Checks whose errors start with `prefix`.
    pub fn new(file: SceneFile<'a>, prefix: String) -> Self {
        Self {
            file,
            prefix,
            body: String::new(),
        }
    }

    /// Checks of the keys of the body called `name` (errors start with
    /// ``body `name`: ``).
    pub fn of_body(file: SceneFile<'a>, name: &str) -> Self {
        Self {
            file,
            prefix: format!("body `{name}`: "),
            body: name.to_owned(),
        }
    }

    /// An error at the line of `span`.
    pub fn fail_at(&self, span: Range<usize>, message: &str) -> SceneError {
        self.file
            .error(Some(span), &format!("{}{message}", self.prefix))
    }

    /// A typed problem with the body's keys ([`SceneError::Key`]) at the
    /// line of `span`, in words `message`.
    pub fn fail_key(&self, span: Range<usize>, problem: KeyProblem, message: &str) -> SceneError {
        SceneError::Key {
            path: self.file.path.to_owned(),
            line: self.file.line_of(span.start),
            body: self.body.clone(),
            problem: Box::new(problem),
            message: one_line(&format!("{}{message}", self.prefix)),
        }
    }

    /// An error at the line of `value`.
    pub fn fail<T>(&self, value: &Spanned<T>, message: &str) -> SceneError {
        self.fail_at(value.span(), message)
    }

    /// The 1-based line of `value`.
    pub fn line_of<T>(&self, value: &Spanned<T>) -> u64 {
        self.file.line_of(value.span().start)
    }

    /// The value of `key`, which must be positive and finite.
    pub fn positive(&self, key: &str, value: &Spanned<f64>) -> Result<f64, SceneError> {
        let v = *value.get_ref();
        if v.is_finite() && v > 0.0 {
            Ok(v)
        } else {
            let message = format!("`{key}` must be positive and finite, got {}", Shortest(v));
            Err(self.fail(value, &message))
        }
    }

    /// The value of `key`, which must be finite numbers.
    pub fn finite<const N: usize>(
        &self,
        key: &str,
        value: &Spanned<[f64; N]>,
    ) -> Result<[f64; N], SceneError> {
        let v = *value.get_ref();
        if v.iter().all(|x| x.is_finite()) {
            Ok(v)
        } else {
            Err(self.fail(value, &format!("`{key}` must be finite numbers")))
        }
    }

    /// The value of `key`, a vector of three finite numbers.
    pub fn vector(&self, key: &str, value: &Spanned<[f64; 3]>) -> Result<DVec3, SceneError> {
        self.finite(key, value).map(DVec3::from_array)
    }
}
