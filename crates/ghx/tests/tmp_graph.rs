use locus_runtime::{Document, Evaluator, NodeRegistry, compare_expected};
#[test]
fn tmp() {
    let mut r = NodeRegistry::new();
    locus_nodes::register(&mut r);
    let path = std::env::var("G").unwrap();
    let text = std::fs::read_to_string(&path).unwrap();
    let doc = Document::parse(&text).unwrap();
    let checked = match doc.check(&r) { Ok(c) => c, Err(e) => panic!("{e:?}") };
    println!("diags {:?}", checked.warnings);
    let mut ev = Evaluator::new(checked.plan);
    ev.evaluate();
    for m in ev.messages() { println!("msg {m:?}"); }
    for (name, t) in ev.outputs() { println!("{name}: {t:?}"); }
    let _ = compare_expected;
    println!("canonical: {}", doc.canonical().unwrap() == text);
}
