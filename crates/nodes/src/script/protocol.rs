//! The messages between the engine and a script worker, and how they are framed on its pipes.
//!
//! A worker is a Python process (`locus._script_worker` run by `python`) that reads requests on its
//! standard input and writes replies on its standard output. Every message is a frame: its
//! length as 4 bytes (little-endian), then that many bytes, written and read with
//! [`codec`](super::codec).
//!
//! 1. When it starts, the worker says [`Reply::Hello`] with the protocol version it speaks and
//!    the version of its `locus` package.
//! 2. The engine sends one [`Request`] per node evaluation: the script, its inputs and outputs,
//!    and the data of *every* iteration, so that a node costs one round trip however many
//!    items it has. A list or tree input's data is sent once per distinct branch or tree (the
//!    request's `shared` table) and iterations refer to it by index.
//! 3. The worker answers with one [`Reply::Done`] per iteration, in order, as each finishes,
//!    so that the engine can hold each iteration to its time limit; or with one
//!    [`Reply::Fatal`] when it cannot run the request at all.

use std::io::{self, Read, Write};

use locus_runtime::{Access, DataTree, Level, Value};

use super::codec::{DecodeError, Decoder, Encoder};

/// The version of this protocol: a worker that speaks another is refused with both versions
/// named (the `locus` package and the engine must come from the same release).
pub const PROTOCOL_VERSION: u32 = 1;

/// The first text of a worker's hello, so that a process that is not a worker (another
/// program answering on its standard output) is recognised at once.
pub const HELLO_MAGIC: &str = "locus-script-worker";

/// The largest frame either side reads (1 GiB): a larger length is a corrupt stream.
pub const MAX_FRAME_BYTES: usize = 1 << 30;

const REQUEST: u8 = 1;
const HELLO: u8 = 2;
const DONE: u8 = 3;
const FATAL: u8 = 4;

/// One input of a script: its name, how it receives data, and its type hint.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ScriptInput {
    /// The variable name in the script.
    pub name: String,
    /// Item, list or tree access.
    pub access: Access,
    /// The type hint as the node's settings name it (canonical form, such as `Point3d`), or
    /// empty for none.
    pub hint: String,
}

/// The data one input has in one iteration.
#[derive(Clone, Debug, PartialEq)]
pub enum InputData {
    /// An item-access input's item (`None`: null or missing).
    Item(Option<Value>),
    /// A list- or tree-access input's data: an index into [`Request::shared`].
    Shared(usize),
}

/// Data sent once and used by several iterations.
#[derive(Clone, Debug, PartialEq)]
pub enum SharedData {
    /// A list-access input's branch.
    List(Vec<Option<Value>>),
    /// A tree-access input's tree.
    Tree(DataTree),
}

/// Everything a worker needs to run a script for every iteration of one node evaluation.
#[derive(Clone, Debug, PartialEq)]
pub struct Request {
    /// The node's id (the file name of the script in tracebacks).
    pub node: String,
    /// The script.
    pub code: String,
    /// Whether inputs arrive as the GhPython compatibility layer's Rhino types.
    pub ghpython: bool,
    /// The time limit of one call of the script, in seconds.
    pub time_limit: f64,
    /// The inputs, in port order.
    pub inputs: Vec<ScriptInput>,
    /// The output names, in port order.
    pub outputs: Vec<String>,
    /// Lists and trees used by the iterations.
    pub shared: Vec<SharedData>,
    /// For every iteration, one entry per input.
    pub iterations: Vec<Vec<InputData>>,
}

/// What one call of the script gave one output.
#[derive(Clone, Debug, PartialEq)]
pub enum OutputData {
    /// The script did not assign the output (or assigned `None`): a null.
    Unset,
    /// One item.
    Item(Option<Value>),
    /// A list (from a Python list, tuple or other iterable).
    List(Vec<Option<Value>>),
    /// A tree (from a dict of paths or a `DataTree`).
    Tree(DataTree),
}

/// What one call of the script did.
#[derive(Clone, Debug, PartialEq)]
pub struct Outcome {
    /// One entry per output, in port order.
    pub outputs: Vec<OutputData>,
    /// What the script printed.
    pub printed: String,
    /// Messages the script added (GhPython's `ghenv.Component.AddRuntimeMessage`).
    pub messages: Vec<(Level, String)>,
    /// The exception that ended the call, as `line N: Type: message`.
    pub error: Option<String>,
}

/// A message from the worker.
#[derive(Clone, Debug, PartialEq)]
pub enum Reply {
    /// The first message of a worker.
    Hello {
        /// The protocol it speaks.
        protocol: u32,
        /// The version of its `locus` package.
        version: String,
        /// The Python version (`3.11.7`).
        python: String,
    },
    /// One iteration's outcome.
    Done(Outcome),
    /// The worker could not run the request (the reason).
    Fatal(String),
}

fn access_byte(a: Access) -> u8 {
    match a {
        Access::Item => 0,
        Access::List => 1,
        Access::Tree => 2,
    }
}

fn level_byte(l: Level) -> u8 {
    match l {
        Level::Remark => 0,
        Level::Warning => 1,
        Level::Error => 2,
    }
}

impl Request {
    /// The request as bytes.
    ///
    /// # Errors
    /// When a value has no exchange form.
    pub fn encode(&self) -> Result<Vec<u8>, String> {
        let mut e = Encoder::new();
        e.u8(REQUEST);
        e.str(&self.node);
        e.str(&self.code);
        e.bool(self.ghpython);
        e.f64(self.time_limit);
        e.count(self.inputs.len());
        for input in &self.inputs {
            e.str(&input.name);
            e.u8(access_byte(input.access));
            e.str(&input.hint);
        }
        e.count(self.outputs.len());
        for name in &self.outputs {
            e.str(name);
        }
        e.count(self.shared.len());
        for s in &self.shared {
            match s {
                SharedData::List(items) => {
                    e.u8(0);
                    e.items(items)?;
                }
                SharedData::Tree(tree) => {
                    e.u8(1);
                    e.tree(tree)?;
                }
            }
        }
        e.count(self.iterations.len());
        for iteration in &self.iterations {
            for data in iteration {
                match data {
                    InputData::Item(v) => {
                        e.u8(0);
                        e.item(v.as_ref())?;
                    }
                    InputData::Shared(k) => {
                        e.u8(1);
                        e.count(*k);
                    }
                }
            }
        }
        Ok(e.into_bytes())
    }

    /// Reads a request, checking every shared index.
    ///
    /// # Errors
    /// When the bytes are not a request.
    pub fn decode(bytes: &[u8]) -> Result<Self, DecodeError> {
        let mut d = Decoder::new(bytes);
        if d.u8()? != REQUEST {
            return Err(DecodeError("not a request".to_owned()));
        }
        let node = d.str()?;
        let code = d.str()?;
        let ghpython = d.bool()?;
        let time_limit = d.f64()?;
        let n = d.count(6)?;
        let inputs = (0..n)
            .map(|_| {
                let name = d.str()?;
                let access = match d.u8()? {
                    0 => Access::Item,
                    1 => Access::List,
                    2 => Access::Tree,
                    other => return Err(DecodeError(format!("unknown access {other}"))),
                };
                Ok(ScriptInput {
                    name,
                    access,
                    hint: d.str()?,
                })
            })
            .collect::<Result<Vec<_>, DecodeError>>()?;
        let n = d.count(4)?;
        let outputs = (0..n).map(|_| d.str()).collect::<Result<Vec<_>, _>>()?;
        let n = d.count(5)?;
        let shared = (0..n)
            .map(|_| match d.u8()? {
                0 => Ok(SharedData::List(d.items()?)),
                1 => Ok(SharedData::Tree(d.tree()?)),
                other => Err(DecodeError(format!("unknown shared data kind {other}"))),
            })
            .collect::<Result<Vec<_>, DecodeError>>()?;
        let n = if inputs.is_empty() {
            // A node without inputs solves once: its iterations take no bytes.
            match d.index()? {
                n @ 0..=1 => n,
                n => {
                    return Err(DecodeError(format!(
                        "{n} iterations of a script without inputs"
                    )));
                }
            }
        } else {
            d.count(2 * inputs.len())?
        };
        let iterations = (0..n)
            .map(|_| {
                inputs
                    .iter()
                    .map(|_| match d.u8()? {
                        0 => Ok(InputData::Item(d.item()?)),
                        1 => {
                            let k = d.index()?;
                            if k >= shared.len() {
                                return Err(DecodeError(format!(
                                    "shared data {k} of {}",
                                    shared.len()
                                )));
                            }
                            Ok(InputData::Shared(k))
                        }
                        other => Err(DecodeError(format!("unknown input data kind {other}"))),
                    })
                    .collect::<Result<Vec<_>, DecodeError>>()
            })
            .collect::<Result<Vec<_>, DecodeError>>()?;
        Ok(Self {
            node,
            code,
            ghpython,
            time_limit,
            inputs,
            outputs,
            shared,
            iterations,
        })
    }
}

impl Reply {
    /// The reply as bytes.
    ///
    /// # Errors
    /// When a value has no exchange form.
    pub fn encode(&self) -> Result<Vec<u8>, String> {
        let mut e = Encoder::new();
        match self {
            Reply::Hello {
                protocol,
                version,
                python,
            } => {
                e.u8(HELLO);
                e.str(HELLO_MAGIC);
                e.count(*protocol as usize);
                e.str(version);
                e.str(python);
            }
            Reply::Done(outcome) => {
                e.u8(DONE);
                e.count(outcome.outputs.len());
                for o in &outcome.outputs {
                    match o {
                        OutputData::Unset => e.u8(0),
                        OutputData::Item(v) => {
                            e.u8(1);
                            e.item(v.as_ref())?;
                        }
                        OutputData::List(items) => {
                            e.u8(2);
                            e.items(items)?;
                        }
                        OutputData::Tree(tree) => {
                            e.u8(3);
                            e.tree(tree)?;
                        }
                    }
                }
                e.str(&outcome.printed);
                e.count(outcome.messages.len());
                for (level, text) in &outcome.messages {
                    e.u8(level_byte(*level));
                    e.str(text);
                }
                match &outcome.error {
                    Some(text) => {
                        e.u8(1);
                        e.str(text);
                    }
                    None => e.u8(0),
                }
            }
            Reply::Fatal(text) => {
                e.u8(FATAL);
                e.str(text);
            }
        }
        Ok(e.into_bytes())
    }

    /// Reads a reply.
    ///
    /// # Errors
    /// When the bytes are not a reply (a value that is not valid is an error too: the worker
    /// checks its values before sending them).
    pub fn decode(bytes: &[u8]) -> Result<Self, DecodeError> {
        let mut d = Decoder::new(bytes);
        match d.u8()? {
            HELLO => {
                let magic = d.str()?;
                if magic != HELLO_MAGIC {
                    return Err(DecodeError(format!(
                        "not a locus script worker ({magic:?})"
                    )));
                }
                Ok(Reply::Hello {
                    protocol: u32::try_from(d.index()?).unwrap_or(u32::MAX),
                    version: d.str()?,
                    python: d.str()?,
                })
            }
            DONE => {
                let n = d.count(1)?;
                let outputs = (0..n)
                    .map(|_| match d.u8()? {
                        0 => Ok(OutputData::Unset),
                        1 => Ok(OutputData::Item(d.item()?)),
                        2 => Ok(OutputData::List(d.items()?)),
                        3 => Ok(OutputData::Tree(d.tree()?)),
                        other => Err(DecodeError(format!("unknown output kind {other}"))),
                    })
                    .collect::<Result<Vec<_>, DecodeError>>()?;
                let printed = d.str()?;
                let n = d.count(5)?;
                let messages = (0..n)
                    .map(|_| {
                        let level = match d.u8()? {
                            0 => Level::Remark,
                            1 => Level::Warning,
                            2 => Level::Error,
                            other => return Err(DecodeError(format!("unknown level {other}"))),
                        };
                        Ok((level, d.str()?))
                    })
                    .collect::<Result<Vec<_>, DecodeError>>()?;
                let error = match d.bool()? {
                    true => Some(d.str()?),
                    false => None,
                };
                Ok(Reply::Done(Outcome {
                    outputs,
                    printed,
                    messages,
                    error,
                }))
            }
            FATAL => Ok(Reply::Fatal(d.str()?)),
            other => Err(DecodeError(format!("unknown reply {other}"))),
        }
    }
}

/// Writes one frame.
///
/// # Errors
/// When the pipe is closed, or the message is larger than [`MAX_FRAME_BYTES`].
pub fn write_frame(w: &mut impl Write, bytes: &[u8]) -> io::Result<()> {
    if bytes.len() > MAX_FRAME_BYTES {
        return Err(io::Error::new(
            io::ErrorKind::InvalidData,
            format!(
                "a message of {} bytes is larger than the limit of {MAX_FRAME_BYTES}",
                bytes.len()
            ),
        ));
    }
    let n = u32::try_from(bytes.len()).unwrap_or(u32::MAX);
    w.write_all(&n.to_le_bytes())?;
    w.write_all(bytes)?;
    w.flush()
}

/// Reads one frame; `None` at the end of the stream (the other side closed it between
/// frames).
///
/// # Errors
/// When the stream ends inside a frame or announces one larger than [`MAX_FRAME_BYTES`].
pub fn read_frame(r: &mut impl Read) -> io::Result<Option<Vec<u8>>> {
    let mut len = [0u8; 4];
    let mut got = 0;
    while got < 4 {
        match r.read(&mut len[got..]) {
            Ok(0) if got == 0 => return Ok(None),
            Ok(0) => return Err(io::ErrorKind::UnexpectedEof.into()),
            Ok(k) => got += k,
            Err(e) if e.kind() == io::ErrorKind::Interrupted => {}
            Err(e) => return Err(e),
        }
    }
    let n = u32::from_le_bytes(len) as usize;
    if n > MAX_FRAME_BYTES {
        return Err(io::Error::new(
            io::ErrorKind::InvalidData,
            format!("a frame of {n} bytes is larger than the limit of {MAX_FRAME_BYTES}"),
        ));
    }
    let mut bytes = vec![0; n];
    r.read_exact(&mut bytes)?;
    Ok(Some(bytes))
}

#[cfg(test)]
mod tests {
    use super::*;
    use locus_kernel::Point3;
    use locus_runtime::{Branch, TreePath};

    #[test]
    fn requests_round_trip() {
        let mut tree = DataTree::new();
        tree.insert(TreePath::new(vec![0, 1]), Branch::from_items(vec![1i64, 2]));
        let request = Request {
            node: "script".to_owned(),
            code: "a = x + 1\nprint(a)".to_owned(),
            ghpython: true,
            time_limit: 2.5,
            inputs: vec![
                ScriptInput {
                    name: "x".to_owned(),
                    access: Access::Item,
                    hint: "float".to_owned(),
                },
                ScriptInput {
                    name: "pts".to_owned(),
                    access: Access::List,
                    hint: String::new(),
                },
                ScriptInput {
                    name: "t".to_owned(),
                    access: Access::Tree,
                    hint: String::new(),
                },
            ],
            outputs: vec!["out".to_owned(), "a".to_owned()],
            shared: vec![
                SharedData::List(vec![Some(Value::Point(Point3::new(1.0, 2.0, 3.0))), None]),
                SharedData::Tree(tree),
            ],
            iterations: vec![
                vec![
                    InputData::Item(Some(Value::Number(1.5))),
                    InputData::Shared(0),
                    InputData::Shared(1),
                ],
                vec![
                    InputData::Item(None),
                    InputData::Shared(0),
                    InputData::Shared(1),
                ],
            ],
        };
        let bytes = request.encode().unwrap();
        assert_eq!(Request::decode(&bytes).unwrap(), request);
        // A shared index past the table is refused.
        let mut bad = request.clone();
        bad.iterations[0][1] = InputData::Shared(7);
        let err = Request::decode(&bad.encode().unwrap()).unwrap_err();
        assert!(err.0.contains("shared data 7 of 2"), "{err}");
    }

    #[test]
    fn replies_round_trip() {
        let mut tree = DataTree::new();
        tree.insert(TreePath::new(vec![3]), Branch::from_items(vec![true]));
        for reply in [
            Reply::Hello {
                protocol: PROTOCOL_VERSION,
                version: "0.1.0".to_owned(),
                python: "3.11.7".to_owned(),
            },
            Reply::Done(Outcome {
                outputs: vec![
                    OutputData::Unset,
                    OutputData::Item(Some(Value::Text("G1".to_owned()))),
                    OutputData::List(vec![None, Some(Value::Integer(4))]),
                    OutputData::Tree(tree),
                ],
                printed: "hello\n".to_owned(),
                messages: vec![(Level::Warning, "careful".to_owned())],
                error: Some("line 3: ZeroDivisionError: division by zero".to_owned()),
            }),
            Reply::Fatal("cannot read the request".to_owned()),
        ] {
            let bytes = reply.encode().unwrap();
            assert_eq!(Reply::decode(&bytes).unwrap(), reply);
        }
    }

    #[test]
    fn frames_round_trip_and_refuse_absurd_lengths() {
        let mut buf = Vec::new();
        write_frame(&mut buf, b"abc").unwrap();
        write_frame(&mut buf, b"").unwrap();
        let mut r = &buf[..];
        assert_eq!(read_frame(&mut r).unwrap().unwrap(), b"abc");
        assert_eq!(read_frame(&mut r).unwrap().unwrap(), b"");
        assert!(read_frame(&mut r).unwrap().is_none());
        let huge = (u32::MAX).to_le_bytes();
        assert!(read_frame(&mut &huge[..]).is_err());
        // A stream that ends inside a frame is an error, not the end.
        let cut = [5u8, 0, 0, 0, 1, 2];
        assert!(read_frame(&mut &cut[..]).is_err());
        assert!(read_frame(&mut &cut[..2]).is_err());
    }
}
