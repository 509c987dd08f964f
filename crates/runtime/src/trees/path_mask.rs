//! The masks of the Path Mapper: tokens, the source and target grammars, and the integer
//! expressions of target masks.
//!
//! Source masks are `{A;B;…}` with an optional `(i)`; target masks are `{e;…}` with an optional
//! `(e)`, where each `e` is an integer expression (`+ - * / \ %`, unary minus, parentheses,
//! whole numbers and names). Parsing is recursive descent over at most [`MAX_MASK_TOKENS`]
//! tokens, so that its depth is bounded for any input. See [`PathMapper`](crate::PathMapper).

use crate::PathMapError;

/// The most tokens a mask may have. Expressions are parsed and evaluated recursively, so this
/// bounds their depth (and stack use) for any input.
pub const MAX_MASK_TOKENS: usize = 1000;

/// The names of the constants available in target masks.
pub(crate) const CONSTANTS: [&str; 3] = ["item_count", "path_count", "path_index"];

/// An integer expression of a target mask; variables are slots of the environment.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Expr {
    Number(i64),
    Var(usize),
    Neg(Box<Expr>),
    Binary(Op, Box<Expr>, Box<Expr>),
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Op {
    Add,
    Sub,
    Mul,
    Div,
    Rem,
}

impl Expr {
    pub(crate) fn uses(&self, slot: usize) -> bool {
        match self {
            Expr::Number(_) => false,
            Expr::Var(s) => *s == slot,
            Expr::Neg(e) => e.uses(slot),
            Expr::Binary(_, a, b) => a.uses(slot) || b.uses(slot),
        }
    }

    pub(crate) fn eval(&self, env: &[i64]) -> Result<i64, String> {
        let overflow = || "arithmetic overflow".to_owned();
        match self {
            Expr::Number(n) => Ok(*n),
            Expr::Var(s) => Ok(env[*s]),
            Expr::Neg(e) => e.eval(env)?.checked_neg().ok_or_else(overflow),
            Expr::Binary(op, a, b) => {
                let (a, b) = (a.eval(env)?, b.eval(env)?);
                if matches!(op, Op::Div | Op::Rem) && b == 0 {
                    return Err("division by zero".to_owned());
                }
                match op {
                    Op::Add => a.checked_add(b),
                    Op::Sub => a.checked_sub(b),
                    Op::Mul => a.checked_mul(b),
                    Op::Div => a.checked_div(b),
                    Op::Rem => a.checked_rem(b),
                }
                .ok_or_else(overflow)
            }
        }
    }
}

#[derive(Clone, Debug, PartialEq)]
enum Token {
    Open(char),
    Close(char),
    Semicolon,
    Op(char),
    Number(i64),
    Name(String),
}

/// A token and the byte offset where it starts.
type Spanned = (Token, usize);

struct Lexer<'a> {
    mask: &'a str,
    tokens: Vec<Spanned>,
    next: usize,
}

impl<'a> Lexer<'a> {
    fn new(mask: &'a str) -> Result<Self, PathMapError> {
        let mut tokens = Vec::new();
        let mut chars = mask.char_indices().peekable();
        while let Some((at, c)) = chars.next() {
            let token = match c {
                c if c.is_whitespace() => continue,
                '{' | '(' => Token::Open(c),
                '}' | ')' => Token::Close(c),
                ';' => Token::Semicolon,
                '+' | '-' | '*' | '/' | '\\' | '%' => Token::Op(c),
                '0'..='9' => {
                    let mut end = at + 1;
                    while let Some(&(i, d)) = chars.peek() {
                        if !d.is_ascii_digit() {
                            break;
                        }
                        end = i + 1;
                        chars.next();
                    }
                    let n = mask[at..end].parse().map_err(|_| {
                        syntax(
                            mask,
                            at,
                            format!("number `{}` is too large", &mask[at..end]),
                        )
                    })?;
                    Token::Number(n)
                }
                c if c.is_alphabetic() || c == '_' => {
                    let mut end = at + c.len_utf8();
                    while let Some(&(i, d)) = chars.peek() {
                        if !(d.is_alphanumeric() || d == '_') {
                            break;
                        }
                        end = i + d.len_utf8();
                        chars.next();
                    }
                    Token::Name(mask[at..end].to_owned())
                }
                other => return Err(syntax(mask, at, format!("unexpected `{other}`"))),
            };
            if tokens.len() == MAX_MASK_TOKENS {
                return Err(syntax(
                    mask,
                    at,
                    format!("the mask is too long (more than {MAX_MASK_TOKENS} tokens)"),
                ));
            }
            tokens.push((token, at));
        }
        Ok(Self {
            mask,
            tokens,
            next: 0,
        })
    }

    fn peek(&self) -> Option<&Token> {
        self.tokens.get(self.next).map(|(t, _)| t)
    }

    /// The byte offset of the next token, or the end of the mask.
    fn at(&self) -> usize {
        self.tokens
            .get(self.next)
            .map_or(self.mask.len(), |(_, at)| *at)
    }

    fn bump(&mut self) -> Option<Spanned> {
        let t = self.tokens.get(self.next).cloned();
        self.next += 1;
        t
    }

    fn eat(&mut self, token: &Token) -> bool {
        if self.peek() == Some(token) {
            self.next += 1;
            true
        } else {
            false
        }
    }

    fn expect(&mut self, token: &Token, what: &str) -> Result<(), PathMapError> {
        if self.eat(token) {
            Ok(())
        } else {
            Err(self.error(format!("expected {what}")))
        }
    }

    fn error(&self, message: String) -> PathMapError {
        syntax(self.mask, self.at(), message)
    }

    fn expect_end(&self) -> Result<(), PathMapError> {
        match self.peek() {
            None => Ok(()),
            Some(_) => Err(self.error("unexpected text after the mask".to_owned())),
        }
    }
}

fn syntax(mask: &str, at: usize, message: String) -> PathMapError {
    PathMapError::Syntax {
        mask: mask.trim().to_owned(),
        column: mask[..at.min(mask.len())].chars().count() + 1,
        message,
    }
}

/// Parses `{A;B;…}` with an optional `(i)`: the path variable names and the item variable.
pub(crate) fn parse_source(mask: &str) -> Result<(Vec<String>, Option<String>), PathMapError> {
    let mut lx = Lexer::new(mask)?;
    let mut seen: Vec<String> = Vec::new();
    let name = |lx: &mut Lexer<'_>, seen: &mut Vec<String>| -> Result<String, PathMapError> {
        let at = lx.at();
        match lx.bump() {
            Some((Token::Name(n), _)) => {
                let key = n.to_lowercase();
                if CONSTANTS.contains(&key.as_str()) {
                    return Err(syntax(
                        mask,
                        at,
                        format!("`{n}` is a constant, not a variable"),
                    ));
                }
                if seen.contains(&key) {
                    return Err(syntax(mask, at, format!("variable `{n}` is used twice")));
                }
                seen.push(key);
                Ok(n)
            }
            Some((Token::Number(_), _)) => Err(syntax(
                mask,
                at,
                "source mask elements must be variable names".to_owned(),
            )),
            _ => Err(syntax(mask, at, "expected a variable name".to_owned())),
        }
    };
    lx.expect(&Token::Open('{'), "`{`")?;
    let mut names = vec![name(&mut lx, &mut seen)?];
    while lx.eat(&Token::Semicolon) {
        names.push(name(&mut lx, &mut seen)?);
    }
    lx.expect(&Token::Close('}'), "`;` or `}`")?;
    let item = if lx.eat(&Token::Open('(')) {
        let n = name(&mut lx, &mut seen)?;
        lx.expect(&Token::Close(')'), "`)`")?;
        Some(n)
    } else {
        None
    };
    lx.expect_end()?;
    Ok((names, item))
}

/// Parses `{expr;…}` with an optional `(expr)`.
pub(crate) fn parse_target(
    mask: &str,
    scope: &[(String, usize)],
) -> Result<(Vec<Expr>, Option<Expr>), PathMapError> {
    let mut lx = Lexer::new(mask)?;
    lx.expect(&Token::Open('{'), "`{`")?;
    let mut path = vec![expr(&mut lx, scope)?];
    while lx.eat(&Token::Semicolon) {
        path.push(expr(&mut lx, scope)?);
    }
    lx.expect(&Token::Close('}'), "`;` or `}`")?;
    let item = if lx.eat(&Token::Open('(')) {
        let e = expr(&mut lx, scope)?;
        lx.expect(&Token::Close(')'), "`)`")?;
        Some(e)
    } else {
        None
    };
    lx.expect_end()?;
    Ok((path, item))
}

/// `expr := term (('+' | '-') term)*`
fn expr(lx: &mut Lexer<'_>, scope: &[(String, usize)]) -> Result<Expr, PathMapError> {
    let mut left = term(lx, scope)?;
    loop {
        let op = match lx.peek() {
            Some(Token::Op('+')) => Op::Add,
            Some(Token::Op('-')) => Op::Sub,
            _ => return Ok(left),
        };
        lx.next += 1;
        let right = term(lx, scope)?;
        left = Expr::Binary(op, Box::new(left), Box::new(right));
    }
}

/// `term := unary (('*' | '/' | '\' | '%') unary)*`
fn term(lx: &mut Lexer<'_>, scope: &[(String, usize)]) -> Result<Expr, PathMapError> {
    let mut left = unary(lx, scope)?;
    loop {
        let op = match lx.peek() {
            Some(Token::Op('*')) => Op::Mul,
            Some(Token::Op('/' | '\\')) => Op::Div,
            Some(Token::Op('%')) => Op::Rem,
            _ => return Ok(left),
        };
        lx.next += 1;
        let right = unary(lx, scope)?;
        left = Expr::Binary(op, Box::new(left), Box::new(right));
    }
}

/// `unary := '-' unary | number | name | '(' expr ')'`
fn unary(lx: &mut Lexer<'_>, scope: &[(String, usize)]) -> Result<Expr, PathMapError> {
    let at = lx.at();
    match lx.bump() {
        Some((Token::Op('-'), _)) => Ok(Expr::Neg(Box::new(unary(lx, scope)?))),
        Some((Token::Number(n), _)) => Ok(Expr::Number(n)),
        Some((Token::Name(name), _)) => match scope
            .iter()
            .find(|(n, _)| n.to_lowercase() == name.to_lowercase())
        {
            Some((_, slot)) => Ok(Expr::Var(*slot)),
            None => {
                let known: Vec<&str> = scope.iter().map(|(n, _)| n.as_str()).collect();
                Err(syntax(
                    lx.mask,
                    at,
                    format!("unknown name `{name}` (known: {})", known.join(", ")),
                ))
            }
        },
        Some((Token::Open('('), _)) => {
            let e = expr(lx, scope)?;
            lx.expect(&Token::Close(')'), "`)`")?;
            Ok(e)
        }
        _ => Err(syntax(
            lx.mask,
            at,
            "expected a number, a name or `(`".to_owned(),
        )),
    }
}

#[cfg(test)]
mod tests {
    use crate::{DataTree, PathMapper};

    #[test]
    fn huge_masks_are_refused_not_overflowing_the_stack() {
        let deep = format!("{{{}A{}}}", "(".repeat(5000), ")".repeat(5000));
        let e = PathMapper::new("{A}", &deep).unwrap_err();
        assert!(e.to_string().contains("the mask is too long"), "{e}");
        let chain = format!("{{A{}}}", "+1".repeat(400));
        let m = PathMapper::new("{A}", &chain).unwrap();
        let tree = DataTree::from_text("{2}:[1]").unwrap();
        assert_eq!(m.apply(&tree).unwrap().to_text(), "{402}:[1]");
        let negations = format!("{{{}A}}", "-".repeat(996));
        let m = PathMapper::new("{A}", &negations).unwrap();
        assert_eq!(m.apply(&tree).unwrap().to_text(), "{2}:[1]");
    }

    #[test]
    fn syntax_errors_point_at_the_problem() {
        let cases = [
            (
                "{A;B}",
                "{C}",
                "invalid mask `{C}` at column 2: unknown name `C` (known: A, B, item_count, path_count, path_index)",
            ),
            (
                "{A;}",
                "{A}",
                "invalid mask `{A;}` at column 4: expected a variable name",
            ),
            (
                "{A;0}",
                "{A}",
                "invalid mask `{A;0}` at column 4: source mask elements must be variable names",
            ),
            (
                "{A;a}",
                "{A}",
                "invalid mask `{A;a}` at column 4: variable `a` is used twice",
            ),
            (
                "{path_index}",
                "{0}",
                "invalid mask `{path_index}` at column 2: `path_index` is a constant, not a variable",
            ),
            ("A;B", "{A}", "invalid mask `A;B` at column 1: expected `{`"),
            (
                "{A B}",
                "{A}",
                "invalid mask `{A B}` at column 4: expected `;` or `}`",
            ),
            (
                "{A}(i",
                "{A}",
                "invalid mask `{A}(i` at column 6: expected `)`",
            ),
            (
                "{A}",
                "{A}(i)",
                "invalid mask `{A}(i)` at column 5: unknown name `i` (known: A, item_count, path_count, path_index)",
            ),
            (
                "{A}",
                "{A+}",
                "invalid mask `{A+}` at column 4: expected a number, a name or `(`",
            ),
            (
                "{A}",
                "{A} x",
                "invalid mask `{A} x` at column 5: unexpected text after the mask",
            ),
            (
                "{A}",
                "{A#}",
                "invalid mask `{A#}` at column 3: unexpected `#`",
            ),
            (
                "{A}",
                "{99999999999999999999}",
                "invalid mask `{99999999999999999999}` at column 2: number `99999999999999999999` is too large",
            ),
            (
                "{}",
                "{0}",
                "invalid mask `{}` at column 2: expected a variable name",
            ),
        ];
        for (source, target, message) in cases {
            let e = PathMapper::new(source, target).unwrap_err();
            assert_eq!(e.to_string(), message, "{source} -> {target}");
        }
    }
}
