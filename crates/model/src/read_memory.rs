//! A memory answering AXI4 read bursts, cycle by cycle: what the command parser
//! (`command_parser`) reads its vertex buffer from, in its model's tests and in the RTL's
//! testbenches alike (the same answers on the same cycles for both).
//!
//! One burst is served at a time, in order: a read address is taken (`ar_ready`) when no
//! burst is being answered and the back-pressure lets it; its first beat comes `latency`
//! cycles after the cycle it was taken in plus one, each later beat on a cycle the
//! back-pressure lets through. Reads outside the memory answer with an error (SLVERR) and
//! zero data, and are counted.

/// Bytes per beat at most (a 256-bit bus).
pub const MAX_BEAT_WORDS: usize = 8;

/// What the memory drives, one cycle.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ReadResponse {
    pub ar_ready: bool,
    pub r_valid: bool,
    /// The beat's little-endian 32-bit words (the bus's width of them).
    pub r_data: [u32; MAX_BEAT_WORDS],
    pub r_last: bool,
    /// RRESP is SLVERR: the beat lies outside the memory.
    pub r_error: bool,
}

impl ReadResponse {
    /// The beat's first four words as one 128-bit number, the first word lowest: RDATA of a
    /// 128-bit bus.
    pub fn data_128(&self) -> u128 {
        self.r_data[..4].iter().rev().fold(0, |acc, &w| acc << 32 | u128::from(w))
    }
}

/// A read burst asked for: the address of its first byte and its beats.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ReadRequest {
    pub addr: u32,
    pub beats: u32,
}

/// The memory and its timing.
pub struct ReadMemory<'a> {
    bytes: &'a [u8],
    /// The buffer's first byte sits at this bus address.
    base: u32,
    beat_bytes: u32,
    latency: u32,
    /// Whether the memory may take an address / send a beat this cycle (back-pressure).
    stall: Box<dyn FnMut() -> bool + 'a>,
    /// The burst being answered: next beat's address, beats left, cycles until the first.
    burst: Option<(u64, u32, u32)>,
    /// Whether `ar_ready` is offered this cycle (decided once per cycle).
    ar_ready: bool,
    beat_ready: bool,
    /// Beats read outside the memory.
    pub outside: u64,
    /// Every burst taken, in order.
    pub requests: Vec<ReadRequest>,
}

impl<'a> ReadMemory<'a> {
    /// `bytes` at bus address `base`, `beat_bytes` a beat (4 to 32), the first beat
    /// `latency` cycles late, and a cycle stalled whenever `stall` says so (asked once per
    /// cycle for the address channel and once for the data channel).
    pub fn new(
        bytes: &'a [u8],
        base: u32,
        beat_bytes: u32,
        latency: u32,
        stall: impl FnMut() -> bool + 'a,
    ) -> ReadMemory<'a> {
        assert!(
            beat_bytes.is_power_of_two() && (4..=4 * MAX_BEAT_WORDS as u32).contains(&beat_bytes),
            "a beat of {beat_bytes} bytes"
        );
        let mut m = ReadMemory {
            bytes,
            base,
            beat_bytes,
            latency,
            stall: Box::new(stall),
            burst: None,
            ar_ready: false,
            beat_ready: false,
            outside: 0,
            requests: Vec::new(),
        };
        m.decide();
        m
    }

    fn decide(&mut self) {
        let stalled_ar = (self.stall)();
        let stalled_r = (self.stall)();
        self.ar_ready = self.burst.is_none() && !stalled_ar;
        self.beat_ready = matches!(self.burst, Some((_, _, 0))) && !stalled_r;
    }

    /// What the memory drives this cycle.
    pub fn response(&self) -> ReadResponse {
        let mut r = ReadResponse { ar_ready: self.ar_ready, ..ReadResponse::default() };
        if let (true, Some((addr, left, _))) = (self.beat_ready, self.burst) {
            r.r_valid = true;
            r.r_last = left == 1;
            for (i, w) in r.r_data.iter_mut().take((self.beat_bytes / 4) as usize).enumerate() {
                match self.word(addr + 4 * i as u64) {
                    Some(v) => *w = v,
                    None => r.r_error = true,
                }
            }
            if r.r_error {
                r.r_data = [0; MAX_BEAT_WORDS];
            }
        }
        r
    }

    fn word(&self, addr: u64) -> Option<u32> {
        let at = usize::try_from(addr.checked_sub(u64::from(self.base))?).ok()?;
        let b = self.bytes.get(at..at.checked_add(4)?)?;
        Some(u32::from_le_bytes([b[0], b[1], b[2], b[3]]))
    }

    /// The clock edge: the master's `ar` (a request offered) and `r_ready` this cycle.
    pub fn clock(&mut self, ar: Option<ReadRequest>, r_ready: bool) {
        let r = self.response();
        if r.r_valid && r_ready {
            self.outside += r.r_error as u64;
            let (addr, left, _) = self.burst.expect("a beat belongs to a burst");
            self.burst = (left > 1).then_some((addr + u64::from(self.beat_bytes), left - 1, 0));
        } else if let Some((addr, left, wait)) = self.burst {
            self.burst = Some((addr, left, wait.saturating_sub(1)));
        }
        if let (true, Some(req)) = (r.ar_ready, ar) {
            assert!(req.beats >= 1, "a burst of no beats");
            self.requests.push(req);
            self.burst = Some((u64::from(req.addr), req.beats, self.latency));
        }
        self.decide();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Steps the memory with one request offered until it is taken and answered; the
    /// cycles at which its beats came.
    fn beats_of(m: &mut ReadMemory, req: ReadRequest) -> Vec<(u32, ReadResponse)> {
        let (mut out, mut offered, mut cycle) = (Vec::new(), Some(req), 0);
        while out.len() < req.beats as usize {
            let r = m.response();
            if r.r_valid {
                out.push((cycle, r));
            }
            let ar = offered;
            if r.ar_ready {
                offered = None;
            }
            m.clock(ar, true);
            cycle += 1;
            assert!(cycle < 1000, "the burst is answered");
        }
        out
    }

    #[test]
    fn data_128_puts_the_first_word_lowest() {
        let r = ReadResponse { r_data: [1, 2, 3, 4, 5, 6, 7, 8], ..ReadResponse::default() };
        assert_eq!(r.data_128(), 4 << 96 | 3 << 64 | 2 << 32 | 1);
    }

    #[test]
    fn first_beat_comes_latency_plus_one_cycles_after_the_address() {
        let bytes: Vec<u8> = (0..64).collect();
        for latency in [0, 3, 20] {
            let mut m = ReadMemory::new(&bytes, 0x1000, 8, latency, || false);
            let beats = beats_of(&mut m, ReadRequest { addr: 0x1008, beats: 3 });
            let cycles: Vec<u32> = beats.iter().map(|b| b.0).collect();
            assert_eq!(cycles, [1 + latency, 2 + latency, 3 + latency]);
            assert_eq!(
                beats[0].1.r_data[..2],
                [u32::from_le_bytes([8, 9, 10, 11]), u32::from_le_bytes([12, 13, 14, 15])]
            );
            assert!(beats[2].1.r_last && !beats[1].1.r_last);
            assert_eq!(m.outside, 0);
        }
    }

    #[test]
    fn reads_outside_answer_an_error() {
        let bytes = [7u8; 16];
        let mut m = ReadMemory::new(&bytes, 0x100, 4, 0, || false);
        let beats = beats_of(&mut m, ReadRequest { addr: 0x10c, beats: 2 });
        assert_eq!((beats[0].1.r_error, beats[0].1.r_data[0]), (false, 0x0707_0707));
        assert_eq!((beats[1].1.r_error, beats[1].1.r_data[0]), (true, 0));
        assert_eq!(m.outside, 1);
    }

    #[test]
    fn back_pressure_spreads_the_beats() {
        let bytes = [0u8; 64];
        let mut n = 0;
        let mut m = ReadMemory::new(&bytes, 0, 4, 0, move || {
            n += 1;
            n % 3 == 0
        });
        let beats = beats_of(&mut m, ReadRequest { addr: 0, beats: 8 });
        assert_eq!(beats.len(), 8);
        let last = beats.last().expect("eight beats").0;
        assert!(last > 8, "some beats were held back: the last came at cycle {last}");
    }
}
