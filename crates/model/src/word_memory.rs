//! A memory answering AXI4 single-beat 32-bit reads and writes, cycle by cycle, with many
//! transactions outstanding: the depth and colour buffers behind `pixel_bus`, in its
//! model's tests and in the RTL's testbenches alike (the same answers on the same cycles
//! for both).
//!
//! Each channel takes a transfer whenever the back-pressure lets it (`ar_ready`,
//! `aw_ready`, `w_ready`, each asked once a cycle). A read is served `latency` cycles after
//! the cycle its address was taken in plus one, in order; a write's address and data pair
//! up in order, and its response comes `latency` cycles after the later of the two plus
//! one. Responses, too, wait for the back-pressure.
//!
//! The timing is the latest AXI4 allows for ordering between reads and writes: a read
//! returns the word as it was when its address was taken, and a write reaches the memory
//! only as its response (B) is sent. A master that reads a word before the response of its
//! write to that word reads the old word, so a missing hazard check shows.
//!
//! Transfers outside the memory are answered with an error (SLVERR), read as zero, written
//! nowhere, and counted.

use std::collections::VecDeque;

/// What the memory drives, one cycle.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct WordResponse {
    pub ar_ready: bool,
    pub r_valid: bool,
    pub r_data: u32,
    /// RRESP is SLVERR: the word lies outside the memory.
    pub r_error: bool,
    pub aw_ready: bool,
    pub w_ready: bool,
    pub b_valid: bool,
    /// BRESP is SLVERR.
    pub b_error: bool,
}

/// What a master drives, one cycle: the transfers it offers and its readiness.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct WordRequest {
    /// A read address offered (`ar_valid`, `ar_addr`).
    pub ar: Option<u32>,
    /// A write address offered (`aw_valid`, `aw_addr`).
    pub aw: Option<u32>,
    /// Write data offered (`w_valid`, `w_data`; every byte strobed).
    pub w: Option<u32>,
    pub r_ready: bool,
    pub b_ready: bool,
}

/// The memory and its timing.
pub struct WordMemory<'a> {
    /// The memory's words, the first at bus address `base`.
    pub words: Vec<u32>,
    base: u32,
    latency: u32,
    stall: Box<dyn FnMut() -> bool + 'a>,
    cycle: u64,
    /// Reads taken: when each may be answered, its data and whether it lay outside.
    reads: VecDeque<(u64, u32, bool)>,
    /// Write addresses and data taken but not yet paired.
    addresses: VecDeque<u32>,
    data: VecDeque<u32>,
    /// Writes paired: when each may be answered, its address and data.
    writes: VecDeque<(u64, u32, u32)>,
    response: WordResponse,
    /// Transfers outside the memory: reads and writes.
    pub outside_reads: u64,
    pub outside_writes: u64,
    /// Every write performed, in order: its bus address and word.
    pub written: Vec<(u32, u32)>,
}

impl<'a> WordMemory<'a> {
    /// `words` at bus address `base` (a multiple of 4), answers `latency` cycles late, and
    /// a channel stalled in a cycle whenever `stall` says so (asked once per channel and
    /// cycle).
    pub fn new(words: Vec<u32>, base: u32, latency: u32, stall: impl FnMut() -> bool + 'a) -> WordMemory<'a> {
        assert_eq!(base % 4, 0, "a memory at {base:#x}: words are 4-byte aligned");
        let mut m = WordMemory {
            words,
            base,
            latency,
            stall: Box::new(stall),
            cycle: 0,
            reads: VecDeque::new(),
            addresses: VecDeque::new(),
            data: VecDeque::new(),
            writes: VecDeque::new(),
            response: WordResponse::default(),
            outside_reads: 0,
            outside_writes: 0,
            written: Vec::new(),
        };
        m.decide();
        m
    }

    /// The index in [`WordMemory::words`] of the word at bus address `addr`, if it lies inside.
    pub fn slot(&self, addr: u32) -> Option<usize> {
        let at = addr.checked_sub(self.base)?;
        (at % 4 == 0).then_some(at as usize / 4).filter(|&i| i < self.words.len())
    }

    /// The word at bus address `addr`; `None` outside.
    pub fn word(&self, addr: u32) -> Option<u32> {
        self.slot(addr).map(|i| self.words[i])
    }

    fn decide(&mut self) {
        let mut r = WordResponse {
            ar_ready: !(self.stall)(),
            aw_ready: !(self.stall)(),
            w_ready: !(self.stall)(),
            ..WordResponse::default()
        };
        if let Some(&(due, data, outside)) = self.reads.front().filter(|_| !(self.stall)()) {
            if due <= self.cycle {
                (r.r_valid, r.r_data, r.r_error) = (true, data, outside);
            }
        }
        if let Some(&(due, addr, _)) = self.writes.front().filter(|_| !(self.stall)()) {
            if due <= self.cycle {
                (r.b_valid, r.b_error) = (true, self.slot(addr).is_none());
            }
        }
        self.response = r;
    }

    /// What the memory drives this cycle.
    pub fn response(&self) -> WordResponse {
        self.response
    }

    /// The clock edge, with what the master drives this cycle.
    pub fn clock(&mut self, q: &WordRequest) {
        let r = self.response;
        let answer = self.cycle + 1 + u64::from(self.latency);
        if r.r_valid && q.r_ready {
            self.reads.pop_front();
        }
        if r.b_valid && q.b_ready {
            let (_, addr, data) = self.writes.pop_front().expect("a response belongs to a write");
            match self.slot(addr) {
                Some(i) => {
                    self.words[i] = data;
                    self.written.push((addr, data));
                }
                None => self.outside_writes += 1,
            }
        }
        if let (true, Some(addr)) = (r.ar_ready, q.ar) {
            let word = self.word(addr);
            self.outside_reads += word.is_none() as u64;
            self.reads.push_back((answer, word.unwrap_or(0), word.is_none()));
        }
        if let (true, Some(addr)) = (r.aw_ready, q.aw) {
            self.addresses.push_back(addr);
        }
        if let (true, Some(data)) = (r.w_ready, q.w) {
            self.data.push_back(data);
        }
        while !self.addresses.is_empty() && !self.data.is_empty() {
            let (addr, data) = (self.addresses.pop_front(), self.data.pop_front());
            self.writes.push_back((answer, addr.expect("an address"), data.expect("data")));
        }
        self.cycle += 1;
        self.decide();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Steps `m`, offering `q` until each of its transfers is taken; the cycles at which
    /// the read data and the write response came.
    fn serve(m: &mut WordMemory, mut q: WordRequest) -> (Option<(u64, u32)>, Option<u64>) {
        let (mut read, mut written) = (None, None);
        q.r_ready = true;
        q.b_ready = true;
        for cycle in 0..100 {
            let r = m.response();
            if r.r_valid {
                read = Some((cycle, r.r_data));
            }
            if r.b_valid {
                written = Some(cycle);
            }
            let now = q;
            q.ar = q.ar.filter(|_| !r.ar_ready);
            q.aw = q.aw.filter(|_| !r.aw_ready);
            q.w = q.w.filter(|_| !r.w_ready);
            m.clock(&now);
        }
        (read, written)
    }

    #[test]
    fn answers_come_latency_plus_one_cycles_after_the_transfer() {
        for latency in [0, 5] {
            let mut m = WordMemory::new(vec![10, 11, 12], 0x100, latency, || false);
            let (read, _) = serve(&mut m, WordRequest { ar: Some(0x104), ..WordRequest::default() });
            assert_eq!(read, Some((1 + u64::from(latency), 11)));
            let (_, b) = serve(&mut m, WordRequest { aw: Some(0x108), w: Some(7), ..WordRequest::default() });
            assert_eq!(b, Some(1 + u64::from(latency)));
            assert_eq!((m.words[2], m.written.clone()), (7, vec![(0x108, 7)]));
        }
    }

    #[test]
    fn a_write_lands_only_with_its_response() {
        let mut m = WordMemory::new(vec![1], 0, 3, || false);
        let w = WordRequest { aw: Some(0), w: Some(9), r_ready: true, b_ready: true, ..WordRequest::default() };
        m.clock(&w);
        let read = WordRequest { ar: Some(0), r_ready: true, b_ready: true, ..WordRequest::default() };
        m.clock(&read);
        let mut seen = None;
        for _ in 0..10 {
            if m.response().r_valid {
                seen = Some(m.response().r_data);
            }
            m.clock(&WordRequest { r_ready: true, b_ready: true, ..WordRequest::default() });
        }
        assert_eq!((seen, m.words[0]), (Some(1), 9), "the read taken before the response sees the old word");
    }

    #[test]
    fn outside_transfers_answer_an_error_and_write_nothing() {
        let mut m = WordMemory::new(vec![5; 4], 0x40, 0, || false);
        let (read, _) =
            serve(&mut m, WordRequest { ar: Some(0x50), aw: Some(0x3c), w: Some(1), ..WordRequest::default() });
        assert_eq!(read, Some((1, 0)));
        assert_eq!((m.outside_reads, m.outside_writes, m.words.clone()), (1, 1, vec![5; 4]));
    }
}
