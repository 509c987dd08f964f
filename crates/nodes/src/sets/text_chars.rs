//! Sets › Text and Sequence, texts by character: Characters, Text Fragment, Text Trim and
//! Char Sequence.
//!
//! Characters are Unicode scalar values (Rust `char`s). .NET, which Grasshopper is built on,
//! counts UTF-16 code units, so for a character outside the Basic Multilingual Plane (an emoji)
//! indices and Unicode values differ from Grasshopper's; for every other text they agree.

use locus_runtime::{DataType, NodeError, NodeRegistry, NodeType, Port, Value};

use super::text::composite_format;
use crate::maths::sequence::MAX_SEQUENCE_LENGTH;

/// Id of [`characters`].
pub const CHARACTERS: &str = "sets.characters";
/// Id of [`text_fragment`].
pub const TEXT_FRAGMENT: &str = "sets.text_fragment";
/// Id of [`text_trim`].
pub const TEXT_TRIM: &str = "sets.text_trim";
/// Id of [`char_sequence`].
pub const CHAR_SEQUENCE: &str = "sets.char_sequence";

/// Char Sequence's default pool: the capital letters.
pub const DEFAULT_CHAR_POOL: &str = "ABCDEFGHIJKLMNOPQRSTUVWXYZ";

/// Registers the character nodes.
pub fn register(registry: &mut NodeRegistry) {
    for t in [characters(), text_fragment(), text_trim(), char_sequence()] {
        registry.register(t);
    }
}

fn text_node(id: &str, name: &str, nickname: &str) -> NodeType {
    NodeType::new(id, name, nickname, "Sets").subcategory("Text")
}

/// Characters \[Chars\]: a text broken into characters.
pub fn characters() -> NodeType {
    text_node(CHARACTERS, "Characters", "Chars")
        .gh_guid("86503240-d884-43f9-9323-efe30488a6e1")
        .description(
            "Breaks text into its individual characters, each with its Unicode value (code \
             point). An empty text gives empty lists.",
        )
        .input(Port::new("Text", "T", DataType::Text).doc("The text to split."))
        .output(
            Port::new("Result", "C", DataType::Text)
                .list()
                .doc("The characters of T, one text each."),
        )
        .output(
            Port::new("Unicode", "U", DataType::Integer)
                .list()
                .doc("The Unicode value of each character."),
        )
        .solve(|s| {
            let t = s.item::<String>(0)?;
            s.set_list(0, t.chars().map(String::from).collect::<Vec<_>>());
            s.set_list(
                1,
                t.chars()
                    .map(|c| i64::from(u32::from(c)))
                    .collect::<Vec<_>>(),
            );
            Ok(())
        })
}

/// Text Fragment \[Fragment\]: the characters of a text from an index on.
pub fn text_fragment() -> NodeType {
    text_node(TEXT_FRAGMENT, "Text Fragment", "Fragment")
        .gh_guid("07e0811f-034a-4504-bca0-2d03b2c46217")
        .description(
            "Extracts a fragment of text: N characters from the zero-based index i on, or all \
             the rest without N. A fragment running past the end is cut there and a start past \
             the end gives an empty text; a negative start or count is an error.",
        )
        .input(Port::new("Text", "T", DataType::Text).doc("The text to operate on."))
        .input(
            Port::new("Start", "i", DataType::Integer)
                .doc("The zero-based index of the first character to copy; default 0.")
                .default_value(0_i64),
        )
        .input(
            Port::new("Count", "N", DataType::Integer)
                .optional()
                .doc("The number of characters to copy; optional, all the rest when absent."),
        )
        .output(Port::new("Fragment", "F", DataType::Text).doc("The text fragment."))
        .solve(|s| {
            let t = s.item::<String>(0)?;
            let start = *s.item::<i64>(1)?;
            let start = usize::try_from(start)
                .map_err(|_| NodeError(format!("start {start} is negative")))?;
            let count = match s.item_opt::<i64>(2) {
                None => usize::MAX,
                Some(&n) => {
                    usize::try_from(n).map_err(|_| NodeError(format!("count {n} is negative")))?
                }
            };
            s.set(0, t.chars().skip(start).take(count).collect::<String>());
            Ok(())
        })
}

/// Text Trim \[Trim\]: whitespace removed from the ends of a text.
pub fn text_trim() -> NodeType {
    text_node(TEXT_TRIM, "Text Trim", "Trim")
        .gh_guid("e4cb7168-5e32-4c54-b425-5a31c6fd685a")
        .description(
            "Removes whitespace characters (Unicode's White_Space: spaces, tabs, line breaks, \
             no-break spaces, …) from the start and/or the end of a text.",
        )
        .input(Port::new("Text", "T", DataType::Text).doc("The text to trim."))
        .input(
            Port::new("Start", "S", DataType::Boolean)
                .doc("Whether whitespace at the start is removed; default true.")
                .default_value(true),
        )
        .input(
            Port::new("End", "E", DataType::Boolean)
                .doc("Whether whitespace at the end is removed; default true.")
                .default_value(true),
        )
        .output(Port::new("Result", "R", DataType::Text).doc("The trimmed text."))
        .lift3(|t: &String, start: &bool, end: &bool| {
            let mut r = t.as_str();
            if *start {
                r = r.trim_start();
            }
            if *end {
                r = r.trim_end();
            }
            Ok(r.to_owned())
        })
}

/// The `n`-th tag (from 1) of a pool in bijective numeration: A, B, …, Z, AA, AB, ….
fn tag(mut n: u64, pool: &[char]) -> String {
    let base = pool.len() as u64;
    let mut digits = Vec::new();
    while n > 0 {
        n -= 1;
        digits.push(pool[(n % base) as usize]);
        n /= base;
    }
    digits.iter().rev().collect()
}

/// Char Sequence \[CharSeq\]: a sequence of character tags A, B, …, Z, AA, AB, ….
pub fn char_sequence() -> NodeType {
    NodeType::new(CHAR_SEQUENCE, "Char Sequence", "CharSeq", "Sets")
        .subcategory("Sequence")
        .gh_guid("01640871-69ea-40ac-9380-4660d6d28bd2")
        .description(
            "Creates a sequence of textual character tags, counting in the characters of the \
             pool as digits the way spreadsheet columns are named: with the pool A to Z, A, B, \
             …, Z, AA, AB, …, AZ, BA, …. Each tag is put into the format mask at {0} (a .NET \
             composite format, as Format reads it). A count of 0 or less, or an empty pool, \
             gives an empty list; more than 10,000,000 tags are an error.",
        )
        .input(
            Port::new("Count", "C", DataType::Integer)
                .doc("The number of elements in the sequence; default 10.")
                .default_value(10_i64),
        )
        .input(
            Port::new("Char Pool", "P", DataType::Text)
                .doc("The characters available to the sequence; default A to Z.")
                .default_value(DEFAULT_CHAR_POOL.to_owned()),
        )
        .input(
            Port::new("Format", "F", DataType::Text)
                .optional()
                .doc("The formatting mask, {0} standing for the tag; optional, default {0}."),
        )
        .output(
            Port::new("Sequence", "S", DataType::Text)
                .list()
                .doc("The sequence of character tags."),
        )
        .solve(|s| {
            let count = *s.item::<i64>(0)?;
            let pool: Vec<char> = s.item::<String>(1)?.chars().collect();
            let format = s.item_opt::<String>(2).cloned();
            if count > MAX_SEQUENCE_LENGTH as i64 {
                return Err(NodeError(format!(
                    "a count of {count} is more than the {MAX_SEQUENCE_LENGTH} tags allowed"
                )));
            }
            if count <= 0 || pool.is_empty() {
                s.set_list::<String>(0, Vec::new());
                return Ok(());
            }
            let mut out = Vec::with_capacity(usize::try_from(count).unwrap_or(0));
            for n in 1..=count.unsigned_abs() {
                let t = tag(n, &pool);
                out.push(match &format {
                    Some(f) => composite_format(f, &[Some(Value::Text(t))])?,
                    None => t,
                });
            }
            s.set_list(0, out);
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use locus_runtime::{DataTree, Level, NodeCall};

    use super::*;
    use crate::sets::test_support::{assert_clean, messages};
    use crate::test_support::all;

    fn text(t: &str) -> DataTree {
        DataTree::from_item(t.to_owned())
    }

    #[test]
    fn characters_and_their_unicode_values() {
        let r = NodeCall::new(&characters()).input(text("Añ €")).run();
        assert_clean(&r);
        assert_eq!(all::<String>(&r.outputs[0]), ["A", "ñ", " ", "€"]);
        assert_eq!(all::<i64>(&r.outputs[1]), [65, 241, 32, 8364]);
        let r = NodeCall::new(&characters()).input(text("")).run();
        assert!(r.outputs[0].has_no_items());
    }

    #[test]
    fn text_fragment_clips_and_rejects_negative_numbers() {
        let node = text_fragment();
        let frag = |start: i64, count: Option<i64>| {
            let mut call = NodeCall::new(&node)
                .input(text("Grasshopper"))
                .input(DataTree::from_item(start));
            if let Some(n) = count {
                call = call.input(DataTree::from_item(n));
            }
            call.run()
        };
        assert_eq!(all::<String>(&frag(5, None).outputs[0]), ["hopper"]);
        assert_eq!(all::<String>(&frag(0, Some(5)).outputs[0]), ["Grass"]);
        assert_eq!(all::<String>(&frag(8, Some(10)).outputs[0]), ["per"]);
        assert_eq!(all::<String>(&frag(20, None).outputs[0]), [""]);
        assert_eq!(
            messages(&frag(-1, None), Level::Error),
            ["start -1 is negative"]
        );
        assert_eq!(
            messages(&frag(0, Some(-2)), Level::Error),
            ["count -2 is negative"]
        );
    }

    #[test]
    fn text_trim_at_either_end() {
        let trim = |s: bool, e: bool| {
            let r = NodeCall::new(&text_trim())
                .input(text(" \t a b \n"))
                .input(DataTree::from_item(s))
                .input(DataTree::from_item(e))
                .run();
            all::<String>(&r.outputs[0]).remove(0)
        };
        assert_eq!(trim(true, true), "a b");
        assert_eq!(trim(true, false), "a b \n");
        assert_eq!(trim(false, true), " \t a b");
        assert_eq!(trim(false, false), " \t a b \n");
    }

    #[test]
    fn char_sequence_counts_like_spreadsheet_columns() {
        let r = NodeCall::new(&char_sequence())
            .input(DataTree::from_item(30_i64))
            .run();
        assert_clean(&r);
        let tags = all::<String>(&r.outputs[0]);
        assert_eq!(tags[..3], ["A", "B", "C"]);
        assert_eq!(tags[25..], ["Z", "AA", "AB", "AC", "AD"]);
        let r = NodeCall::new(&char_sequence())
            .input(DataTree::from_item(7_i64))
            .input(text("ab"))
            .input(text("pt_{0}"))
            .run();
        assert_eq!(
            all::<String>(&r.outputs[0]),
            ["pt_a", "pt_b", "pt_aa", "pt_ab", "pt_ba", "pt_bb", "pt_aaa"]
        );
        assert_eq!(
            tag(26 * 26 + 26, &DEFAULT_CHAR_POOL.chars().collect::<Vec<_>>()),
            "ZZ"
        );
    }

    #[test]
    fn char_sequence_limits_and_empty_cases() {
        let r = NodeCall::new(&char_sequence())
            .input(DataTree::from_item(0_i64))
            .run();
        assert!(r.outputs[0].has_no_items());
        let r = NodeCall::new(&char_sequence())
            .input(DataTree::from_item(3_i64))
            .input(text(""))
            .run();
        assert!(r.outputs[0].has_no_items());
        let r = NodeCall::new(&char_sequence())
            .input(DataTree::from_item(i64::MAX))
            .run();
        assert_eq!(messages(&r, Level::Error).len(), 1);
        let r = NodeCall::new(&char_sequence())
            .input(DataTree::from_item(2_i64))
            .input(text("AB"))
            .input(text("{1}"))
            .run();
        assert_eq!(messages(&r, Level::Error).len(), 1);
    }
}
