//! libFuzzer target: the lcp reader (fuzz/harness.rs).
#![no_main]

#[path = "../harness.rs"]
mod harness;

libfuzzer_sys::fuzz_target!(|data: &[u8]| harness::fuzz(harness::Reader::Lcp, data));
