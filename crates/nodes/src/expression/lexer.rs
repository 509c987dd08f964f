//! Splitting a formula into tokens.
//!
//! Columns are counted in characters from 1, so that an error can point at the fault in the
//! formula as the user typed it. Besides ASCII the lexer accepts the mathematical symbols
//! `−` (minus), `×`, `·` and `•` (times; between vectors Grasshopper writes the dot product
//! `a • b`, which `*` already is), `÷` (divide), `≤`, `≥` and `≠`, and the brackets of
//! Grasshopper's unit vector `[v]`.

use std::fmt;
use std::sync::Arc;

use super::ParseError;

/// What a token is.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum TokenKind {
    /// A number literal such as `2`, `0.5` or `1e-3`.
    Number(f64),
    /// A text literal in double quotes, escapes resolved.
    Text(Arc<str>),
    /// A name: a variable, a constant, a function or a keyword (`and`, `or`, `xor`, `not`,
    /// `true`, `false`).
    Name(String),
    /// `+`
    Plus,
    /// `-` or `−`
    Minus,
    /// `*`, `×`, `·` or `•`
    Star,
    /// `/` or `÷`
    Slash,
    /// `%`
    Percent,
    /// `^`
    Caret,
    /// `&`
    Ampersand,
    /// `<`
    Less,
    /// `<=` or `≤`
    LessEqual,
    /// `>`
    Greater,
    /// `>=` or `≥`
    GreaterEqual,
    /// `=` or `==`
    Equal,
    /// `!=`, `<>` or `≠`
    NotEqual,
    /// `(`
    LeftParen,
    /// `)`
    RightParen,
    /// `[`
    LeftBracket,
    /// `]`
    RightBracket,
    /// `,`
    Comma,
    /// `.` (followed by `x`, `y` or `z`)
    Dot,
    /// `²` (postfix: squared)
    Squared,
    /// `³` (postfix: cubed)
    Cubed,
    /// `°` (postfix: degrees to radians)
    Degree,
    /// `!` (postfix: factorial)
    Bang,
    /// The end of the formula.
    End,
}

impl fmt::Display for TokenKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let symbol = match self {
            TokenKind::Number(x) => return write!(f, "{x}"),
            TokenKind::Text(t) => return write!(f, "\"{t}\""),
            TokenKind::Name(n) => return f.write_str(n),
            TokenKind::Plus => "+",
            TokenKind::Minus => "-",
            TokenKind::Star => "*",
            TokenKind::Slash => "/",
            TokenKind::Percent => "%",
            TokenKind::Caret => "^",
            TokenKind::Ampersand => "&",
            TokenKind::Less => "<",
            TokenKind::LessEqual => "<=",
            TokenKind::Greater => ">",
            TokenKind::GreaterEqual => ">=",
            TokenKind::Equal => "=",
            TokenKind::NotEqual => "!=",
            TokenKind::LeftParen => "(",
            TokenKind::RightParen => ")",
            TokenKind::LeftBracket => "[",
            TokenKind::RightBracket => "]",
            TokenKind::Comma => ",",
            TokenKind::Dot => ".",
            TokenKind::Squared => "²",
            TokenKind::Cubed => "³",
            TokenKind::Degree => "°",
            TokenKind::Bang => "!",
            TokenKind::End => "the end of the expression",
        };
        f.write_str(symbol)
    }
}

/// A token and the column where it starts.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Token {
    /// What the token is.
    pub(crate) kind: TokenKind,
    /// The 1-based character column of its first character.
    pub(crate) column: usize,
}

/// Splits `source` into tokens, ending with [`TokenKind::End`].
///
/// # Errors
/// A [`ParseError`] for a character that starts no token, an unterminated text literal or a
/// malformed number.
pub(crate) fn tokenize(source: &str) -> Result<Vec<Token>, ParseError> {
    let chars: Vec<char> = source.chars().collect();
    let mut tokens = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        let column = i + 1;
        if c.is_whitespace() {
            i += 1;
            continue;
        }
        let next = chars.get(i + 1).copied();
        let (kind, len) = match c {
            '0'..='9' => lex_number(&chars, i)?,
            '.' if next.is_some_and(|n| n.is_ascii_digit()) => lex_number(&chars, i)?,
            '"' => lex_text(&chars, i)?,
            c if c.is_alphabetic() || c == '_' => {
                let mut end = i + 1;
                // `²` and `³` are numeric characters, but postfix operators here (`x²`).
                while end < chars.len()
                    && (chars[end].is_alphanumeric() || chars[end] == '_')
                    && !matches!(chars[end], '²' | '³')
                {
                    end += 1;
                }
                (TokenKind::Name(chars[i..end].iter().collect()), end - i)
            }
            '+' => (TokenKind::Plus, 1),
            '-' | '−' => (TokenKind::Minus, 1),
            '*' | '×' | '·' | '•' => (TokenKind::Star, 1),
            '/' | '÷' => (TokenKind::Slash, 1),
            '%' => (TokenKind::Percent, 1),
            '^' => (TokenKind::Caret, 1),
            '&' => (TokenKind::Ampersand, 1),
            '(' => (TokenKind::LeftParen, 1),
            ')' => (TokenKind::RightParen, 1),
            '[' => (TokenKind::LeftBracket, 1),
            ']' => (TokenKind::RightBracket, 1),
            ',' => (TokenKind::Comma, 1),
            '.' => (TokenKind::Dot, 1),
            '≤' => (TokenKind::LessEqual, 1),
            '≥' => (TokenKind::GreaterEqual, 1),
            '≠' => (TokenKind::NotEqual, 1),
            '<' => match next {
                Some('=') => (TokenKind::LessEqual, 2),
                Some('>') => (TokenKind::NotEqual, 2),
                _ => (TokenKind::Less, 1),
            },
            '>' => match next {
                Some('=') => (TokenKind::GreaterEqual, 2),
                _ => (TokenKind::Greater, 1),
            },
            '=' => match next {
                Some('=') => (TokenKind::Equal, 2),
                _ => (TokenKind::Equal, 1),
            },
            '!' if next == Some('=') => (TokenKind::NotEqual, 2),
            '!' => (TokenKind::Bang, 1),
            '²' => (TokenKind::Squared, 1),
            '³' => (TokenKind::Cubed, 1),
            '°' => (TokenKind::Degree, 1),
            other => {
                return Err(ParseError::new(
                    format!("unexpected character \"{other}\""),
                    column,
                ));
            }
        };
        tokens.push(Token { kind, column });
        i += len;
    }
    tokens.push(Token {
        kind: TokenKind::End,
        column: chars.len() + 1,
    });
    Ok(tokens)
}

/// Lexes a number starting at `start`: digits, an optional fraction and an optional exponent.
fn lex_number(chars: &[char], start: usize) -> Result<(TokenKind, usize), ParseError> {
    let digits = |mut i: usize| {
        while i < chars.len() && chars[i].is_ascii_digit() {
            i += 1;
        }
        i
    };
    let mut end = digits(start);
    if chars.get(end) == Some(&'.') && chars.get(end + 1).is_some_and(char::is_ascii_digit) {
        end = digits(end + 1);
    } else if chars.get(end) == Some(&'.')
        && !chars
            .get(end + 1)
            .is_some_and(|c| c.is_alphabetic() || *c == '_')
    {
        // A trailing point, as in `2.`, belongs to the number.
        end += 1;
    }
    if matches!(chars.get(end), Some('e' | 'E')) {
        let mut k = end + 1;
        if matches!(chars.get(k), Some('+' | '-')) {
            k += 1;
        }
        if chars.get(k).is_some_and(char::is_ascii_digit) {
            end = digits(k);
        }
    }
    let text: String = chars[start..end].iter().collect();
    match text.parse::<f64>() {
        Ok(x) => Ok((TokenKind::Number(x), end - start)),
        Err(_) => Err(ParseError::new(
            format!("\"{text}\" is not a number"),
            start + 1,
        )),
    }
}

/// Lexes a text literal starting at the opening quote; `\"` and `\\` are escapes.
fn lex_text(chars: &[char], start: usize) -> Result<(TokenKind, usize), ParseError> {
    let mut text = String::new();
    let mut i = start + 1;
    while i < chars.len() {
        match chars[i] {
            '"' => return Ok((TokenKind::Text(Arc::from(text.as_str())), i + 1 - start)),
            '\\' if matches!(chars.get(i + 1), Some('"' | '\\')) => {
                text.push(chars[i + 1]);
                i += 2;
            }
            c => {
                text.push(c);
                i += 1;
            }
        }
    }
    Err(ParseError::new("unterminated text", start + 1))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn kinds(source: &str) -> Vec<TokenKind> {
        tokenize(source)
            .unwrap()
            .into_iter()
            .map(|t| t.kind)
            .collect()
    }

    #[test]
    fn numbers_names_and_operators() {
        assert_eq!(
            kinds("2.5*x1 <= 1e-3"),
            vec![
                TokenKind::Number(2.5),
                TokenKind::Star,
                TokenKind::Name("x1".into()),
                TokenKind::LessEqual,
                TokenKind::Number(1e-3),
                TokenKind::End,
            ]
        );
    }

    #[test]
    fn a_point_after_a_name_is_a_member_access() {
        assert_eq!(
            kinds("p.x + .5"),
            vec![
                TokenKind::Name("p".into()),
                TokenKind::Dot,
                TokenKind::Name("x".into()),
                TokenKind::Plus,
                TokenKind::Number(0.5),
                TokenKind::End,
            ]
        );
    }

    #[test]
    fn an_e_not_followed_by_digits_is_not_an_exponent() {
        assert_eq!(
            kinds("2e"),
            vec![
                TokenKind::Number(2.0),
                TokenKind::Name("e".into()),
                TokenKind::End
            ]
        );
    }

    #[test]
    fn number_forms() {
        assert_eq!(
            kinds("2. 6.02E23 1e+2 == <>"),
            vec![
                TokenKind::Number(2.0),
                TokenKind::Number(6.02e23),
                TokenKind::Number(100.0),
                TokenKind::Equal,
                TokenKind::NotEqual,
                TokenKind::End,
            ]
        );
    }

    #[test]
    fn unicode_operators() {
        assert_eq!(
            kinds("a−b×c÷d≠e"),
            vec![
                TokenKind::Name("a".into()),
                TokenKind::Minus,
                TokenKind::Name("b".into()),
                TokenKind::Star,
                TokenKind::Name("c".into()),
                TokenKind::Slash,
                TokenKind::Name("d".into()),
                TokenKind::NotEqual,
                TokenKind::Name("e".into()),
                TokenKind::End,
            ]
        );
    }

    #[test]
    fn text_with_escapes() {
        assert_eq!(
            kinds(r#""say \"hi\"""#),
            vec![TokenKind::Text(Arc::from(r#"say "hi""#)), TokenKind::End]
        );
    }

    #[test]
    fn errors_name_the_column() {
        let e = tokenize("1 + #").unwrap_err();
        assert_eq!(e.to_string(), "unexpected character \"#\" at column 5");
        let e = tokenize("x = \"abc").unwrap_err();
        assert_eq!(e.to_string(), "unterminated text at column 5");
    }

    #[test]
    fn columns_count_characters_not_bytes() {
        let tokens = tokenize("π × 2").unwrap();
        assert_eq!(tokens[1].column, 3);
        assert_eq!(tokens[2].column, 5);
    }
}
