//! Parsing a formula straight into a [`Program`] of stack operations.
//!
//! The parser is a recursive-descent parser, one function per precedence level (lowest
//! first):
//!
//! ```text
//! expression := or
//! or         := and (("or" | "xor") and)*
//! and        := not ("and" not)*
//! not        := "not" not | comparison
//! comparison := concat (("<" | "<=" | ">" | ">=" | "=" | "!=") concat)?
//! concat     := sum ("&" sum)*
//! sum        := product (("+" | "-") product)*
//! product    := unary (("*" | "/" | "%") unary)*
//! unary      := ("-" | "+") unary | power
//! power      := postfix ("^" unary)?
//! postfix    := primary ("." ("x" | "y" | "z"))*
//! primary    := number | text | "true" | "false" | name | name "(" arguments ")"
//!             | "(" expression ")" | "[" expression "]"
//! ```
//!
//! `[v]` is Grasshopper's unit vector of `v`, the same as `unit(v)`.
//!
//! Chains of operators of one level are loops, so a long sum does not deepen the recursion;
//! only nesting (parentheses, prefix operators, `^`) does, and it is capped at
//! [`MAX_NESTING`] levels so that no formula can overflow the stack.

use super::eval::{Axis, Op, Program};
use super::lexer::{Token, TokenKind, tokenize};
use super::{BinaryOp, Function, Operand, ParseError, UnaryOp};

/// The deepest nesting of parentheses, prefix operators and powers a formula may have.
pub const MAX_NESTING: usize = 64;

/// Compiles `source` with the variables `variables` (matched ignoring case).
pub(crate) fn compile(source: &str, variables: &[&str]) -> Result<Program, ParseError> {
    let tokens = tokenize(source)?;
    let mut parser = Parser {
        tokens,
        pos: 0,
        variables,
        ops: Vec::new(),
        columns: Vec::new(),
        stack: 0,
        max_stack: 0,
        nesting: 0,
    };
    if parser.peek().kind == TokenKind::End {
        return Err(ParseError::new("the expression is empty", 1));
    }
    parser.expression()?;
    let end = parser.peek();
    if end.kind != TokenKind::End {
        return Err(ParseError::new(
            format!("unexpected \"{}\"", end.kind),
            end.column,
        ));
    }
    Ok(Program::new(
        source,
        variables,
        parser.ops,
        parser.columns,
        parser.max_stack,
    ))
}

struct Parser<'a> {
    tokens: Vec<Token>,
    pos: usize,
    variables: &'a [&'a str],
    ops: Vec<Op>,
    /// The column each op reports errors at.
    columns: Vec<usize>,
    /// The stack depth after the ops emitted so far.
    stack: usize,
    max_stack: usize,
    nesting: usize,
}

type Parsed = Result<(), ParseError>;

impl Parser<'_> {
    fn peek(&self) -> &Token {
        // The token list always ends with `End`, and `advance` never moves past it.
        &self.tokens[self.pos.min(self.tokens.len() - 1)]
    }

    fn advance(&mut self) -> Token {
        let t = self.peek().clone();
        if self.pos < self.tokens.len() - 1 {
            self.pos += 1;
        }
        t
    }

    /// Whether the next token is the keyword `word` (any case).
    fn at_keyword(&self, word: &str) -> bool {
        matches!(&self.peek().kind, TokenKind::Name(n) if n.eq_ignore_ascii_case(word))
    }

    fn expect(&mut self, kind: &TokenKind) -> Parsed {
        let t = self.peek();
        if &t.kind == kind {
            self.advance();
            Ok(())
        } else {
            Err(ParseError::new(format!("expected \"{kind}\""), t.column))
        }
    }

    /// Appends an op that changes the stack depth by `delta` (pops are negative).
    fn emit(&mut self, op: Op, column: usize, pops: usize, pushes: usize) {
        self.ops.push(op);
        self.columns.push(column);
        self.stack = self.stack.saturating_sub(pops) + pushes;
        self.max_stack = self.max_stack.max(self.stack);
    }

    /// Runs `f` one nesting level deeper.
    fn nested(&mut self, column: usize, f: impl FnOnce(&mut Self) -> Parsed) -> Parsed {
        if self.nesting >= MAX_NESTING {
            return Err(ParseError::new(
                format!("the expression is nested more than {MAX_NESTING} levels deep"),
                column,
            ));
        }
        self.nesting += 1;
        let r = f(self);
        self.nesting -= 1;
        r
    }

    fn expression(&mut self) -> Parsed {
        self.or()
    }

    fn or(&mut self) -> Parsed {
        self.and()?;
        loop {
            let op = if self.at_keyword("or") {
                BinaryOp::Or
            } else if self.at_keyword("xor") {
                BinaryOp::Xor
            } else {
                return Ok(());
            };
            let column = self.advance().column;
            self.and()?;
            self.emit(Op::Binary(op), column, 2, 1);
        }
    }

    fn and(&mut self) -> Parsed {
        self.not()?;
        while self.at_keyword("and") {
            let column = self.advance().column;
            self.not()?;
            self.emit(Op::Binary(BinaryOp::And), column, 2, 1);
        }
        Ok(())
    }

    fn not(&mut self) -> Parsed {
        if self.at_keyword("not") {
            let column = self.advance().column;
            return self.nested(column, |p| {
                p.not()?;
                p.emit(Op::Unary(UnaryOp::Not), column, 1, 1);
                Ok(())
            });
        }
        self.comparison()
    }

    fn comparison_op(&self) -> Option<BinaryOp> {
        Some(match self.peek().kind {
            TokenKind::Less => BinaryOp::Less,
            TokenKind::LessEqual => BinaryOp::LessEqual,
            TokenKind::Greater => BinaryOp::Greater,
            TokenKind::GreaterEqual => BinaryOp::GreaterEqual,
            TokenKind::Equal => BinaryOp::Equal,
            TokenKind::NotEqual => BinaryOp::NotEqual,
            _ => return None,
        })
    }

    fn comparison(&mut self) -> Parsed {
        self.concat()?;
        if let Some(op) = self.comparison_op() {
            let column = self.advance().column;
            self.concat()?;
            self.emit(Op::Binary(op), column, 2, 1);
            if self.comparison_op().is_some() {
                return Err(ParseError::new(
                    "comparisons cannot be chained (use \"and\")",
                    self.peek().column,
                ));
            }
        }
        Ok(())
    }

    fn concat(&mut self) -> Parsed {
        self.sum()?;
        while self.peek().kind == TokenKind::Ampersand {
            let column = self.advance().column;
            self.sum()?;
            self.emit(Op::Binary(BinaryOp::Concatenate), column, 2, 1);
        }
        Ok(())
    }

    fn sum(&mut self) -> Parsed {
        self.product()?;
        loop {
            let op = match self.peek().kind {
                TokenKind::Plus => BinaryOp::Add,
                TokenKind::Minus => BinaryOp::Subtract,
                _ => return Ok(()),
            };
            let column = self.advance().column;
            self.product()?;
            self.emit(Op::Binary(op), column, 2, 1);
        }
    }

    fn product(&mut self) -> Parsed {
        self.unary()?;
        loop {
            let op = match self.peek().kind {
                TokenKind::Star => BinaryOp::Multiply,
                TokenKind::Slash => BinaryOp::Divide,
                TokenKind::Percent => BinaryOp::Modulus,
                _ => return Ok(()),
            };
            let column = self.advance().column;
            self.unary()?;
            self.emit(Op::Binary(op), column, 2, 1);
        }
    }

    fn unary(&mut self) -> Parsed {
        let op = match self.peek().kind {
            TokenKind::Minus => UnaryOp::Negate,
            TokenKind::Plus => UnaryOp::Plus,
            _ => return self.power(),
        };
        let column = self.advance().column;
        self.nested(column, |p| {
            p.unary()?;
            p.emit(Op::Unary(op), column, 1, 1);
            Ok(())
        })
    }

    fn power(&mut self) -> Parsed {
        self.postfix()?;
        if self.peek().kind == TokenKind::Caret {
            let column = self.advance().column;
            self.nested(column, |p| {
                p.unary()?;
                p.emit(Op::Binary(BinaryOp::Power), column, 2, 1);
                Ok(())
            })?;
        }
        Ok(())
    }

    fn postfix(&mut self) -> Parsed {
        self.primary()?;
        loop {
            let op = match self.peek().kind {
                TokenKind::Dot => None,
                TokenKind::Squared => Some(UnaryOp::Squared),
                TokenKind::Cubed => Some(UnaryOp::Cubed),
                TokenKind::Degree => Some(UnaryOp::Radians),
                TokenKind::Bang => Some(UnaryOp::Factorial),
                _ => return Ok(()),
            };
            let column = self.advance().column;
            if let Some(op) = op {
                self.emit(Op::Unary(op), column, 1, 1);
                continue;
            }
            let t = self.advance();
            let axis = match &t.kind {
                TokenKind::Name(n) if n.eq_ignore_ascii_case("x") => Axis::X,
                TokenKind::Name(n) if n.eq_ignore_ascii_case("y") => Axis::Y,
                TokenKind::Name(n) if n.eq_ignore_ascii_case("z") => Axis::Z,
                _ => {
                    return Err(ParseError::new("expected x, y or z after \".\"", t.column));
                }
            };
            self.emit(Op::Member(axis), column, 1, 1);
        }
    }

    fn primary(&mut self) -> Parsed {
        let t = self.advance();
        match t.kind {
            TokenKind::Number(x) => {
                self.emit(Op::Push(Operand::Number(x)), t.column, 0, 1);
                Ok(())
            }
            TokenKind::Text(s) => {
                self.emit(Op::Push(Operand::Text(s)), t.column, 0, 1);
                Ok(())
            }
            TokenKind::LeftParen => self.nested(t.column, |p| {
                p.expression()?;
                p.expect(&TokenKind::RightParen)
            }),
            TokenKind::LeftBracket => self.nested(t.column, |p| {
                p.expression()?;
                p.expect(&TokenKind::RightBracket)?;
                p.emit(Op::Call(Function::Unit, 1), t.column, 1, 1);
                Ok(())
            }),
            TokenKind::Name(name) => {
                if self.peek().kind == TokenKind::LeftParen {
                    self.advance();
                    self.nested(t.column, |p| p.call(&name, t.column))
                } else {
                    self.name(&name, t.column)
                }
            }
            TokenKind::End => Err(ParseError::new(
                "unexpected end of the expression",
                t.column,
            )),
            other => Err(ParseError::new(format!("unexpected \"{other}\""), t.column)),
        }
    }

    /// A name that is not called: a keyword literal, a variable or a constant.
    fn name(&mut self, name: &str, column: usize) -> Parsed {
        let lower = name.to_lowercase();
        let op = match lower.as_str() {
            "true" => Op::Push(Operand::Boolean(true)),
            "false" => Op::Push(Operand::Boolean(false)),
            "and" | "or" | "xor" | "not" => {
                return Err(ParseError::new(format!("unexpected \"{name}\""), column));
            }
            _ => {
                if let Some(i) = self
                    .variables
                    .iter()
                    .position(|v| v.to_lowercase() == lower)
                {
                    Op::Load(i)
                } else if lower == "pi" || lower == "π" {
                    Op::Push(Operand::Number(std::f64::consts::PI))
                } else if lower == "e" {
                    Op::Push(Operand::Number(std::f64::consts::E))
                } else {
                    let hint = if self.variables.is_empty() {
                        String::new()
                    } else {
                        format!(" (the variables are {})", self.variables.join(", "))
                    };
                    return Err(ParseError::new(
                        format!("unknown name \"{name}\"{hint}"),
                        column,
                    ));
                }
            }
        };
        self.emit(op, column, 0, 1);
        Ok(())
    }

    /// A function call; the opening parenthesis has been read.
    fn call(&mut self, name: &str, column: usize) -> Parsed {
        if name.eq_ignore_ascii_case("if") {
            return self.conditional(column);
        }
        let Some(function) = Function::from_name(name) else {
            return Err(ParseError::new(
                format!("unknown function \"{name}\""),
                column,
            ));
        };
        let mut count = 0;
        if self.peek().kind == TokenKind::RightParen {
            self.advance();
        } else {
            loop {
                self.expression()?;
                count += 1;
                let t = self.advance();
                match t.kind {
                    TokenKind::Comma => {}
                    TokenKind::RightParen => break,
                    _ => {
                        return Err(ParseError::new("expected \",\" or \")\"", t.column));
                    }
                }
            }
        }
        let (least, most) = function.arity();
        if count < least || most.is_some_and(|m| count > m) {
            let wanted = match (least, most) {
                (1, Some(1)) => "1 argument".to_owned(),
                (l, Some(m)) if l == m => format!("{l} arguments"),
                (l, Some(m)) => format!("{l} or {m} arguments"),
                (1, None) => "at least 1 argument".to_owned(),
                (l, None) => format!("at least {l} arguments"),
            };
            return Err(ParseError::new(
                format!("{} takes {wanted}, not {count}", function.name()),
                column,
            ));
        }
        self.emit(Op::Call(function, count), column, count, 1);
        Ok(())
    }

    /// `if(condition, then, else)`, compiled to jumps so only one branch runs.
    fn conditional(&mut self, column: usize) -> Parsed {
        self.expression()?;
        self.expect(&TokenKind::Comma)?;
        let jump_unless = self.ops.len();
        self.emit(Op::JumpUnless(0), column, 1, 0);
        let before = self.stack;
        self.expression()?;
        self.expect(&TokenKind::Comma)?;
        let jump = self.ops.len();
        self.emit(Op::Jump(0), column, 0, 0);
        self.ops[jump_unless] = Op::JumpUnless(self.ops.len());
        // At run time only one branch pushes its value.
        self.stack = before;
        self.expression()?;
        self.ops[jump] = Op::Jump(self.ops.len());
        let t = self.advance();
        if t.kind != TokenKind::RightParen {
            let message = if t.kind == TokenKind::Comma {
                "if takes 3 arguments (condition, then, else)"
            } else {
                "expected \")\""
            };
            return Err(ParseError::new(message, t.column));
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn error(source: &str, variables: &[&str]) -> String {
        compile(source, variables).unwrap_err().to_string()
    }

    #[test]
    fn errors_name_the_fault_and_its_column() {
        assert_eq!(error("(x + 1", &["x"]), "expected \")\" at column 7");
        assert_eq!(
            error("x +", &["x"]),
            "unexpected end of the expression at column 4"
        );
        assert_eq!(error("", &[]), "the expression is empty at column 1");
        assert_eq!(error("2 x", &["x"]), "unexpected \"x\" at column 3");
        assert_eq!(
            error("x + z", &["x", "y"]),
            "unknown name \"z\" (the variables are x, y) at column 5"
        );
        assert_eq!(error("foo(1)", &[]), "unknown function \"foo\" at column 1");
        assert_eq!(
            error("sqrt(1, 2)", &[]),
            "sqrt takes 1 argument, not 2 at column 1"
        );
        assert_eq!(
            error("log()", &[]),
            "log takes 1 or 2 arguments, not 0 at column 1"
        );
        assert_eq!(
            error("1 < 2 < 3", &[]),
            "comparisons cannot be chained (use \"and\") at column 7"
        );
        assert_eq!(
            error("p.w", &["p"]),
            "expected x, y or z after \".\" at column 3"
        );
        assert_eq!(
            error("max(1 2)", &[]),
            "expected \",\" or \")\" at column 7"
        );
        assert_eq!(
            error("if(1, 2, 3, 4)", &[]),
            "if takes 3 arguments (condition, then, else) at column 11"
        );
        assert_eq!(
            error("x and", &["x"]),
            "unexpected end of the expression at column 6"
        );
        assert_eq!(error("* 2", &[]), "unexpected \"*\" at column 1");
    }

    #[test]
    fn deep_nesting_is_an_error_not_a_stack_overflow() {
        let deep = format!("{}1{}", "(".repeat(10_000), ")".repeat(10_000));
        assert!(error(&deep, &[]).contains("nested more than 64 levels"));
        let minus = format!("{}1", "-".repeat(10_000));
        assert!(error(&minus, &[]).contains("nested"));
        let power = vec!["2"; 10_000].join("^");
        assert!(error(&power, &[]).contains("nested"));
    }

    #[test]
    fn long_flat_chains_are_fine() {
        let long = vec!["1"; 100_000].join("+");
        let program = compile(&long, &[]).unwrap();
        assert_eq!(program.max_stack(), 2);
    }

    #[test]
    fn stack_depth_is_tracked_through_if() {
        let program = compile("if(x > 0, x * (x + 1), 0)", &["x"]).unwrap();
        assert_eq!(program.max_stack(), 3);
    }
}
