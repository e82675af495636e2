// Icarus Verilog replay of `raster_top` (hdl-out/raster_top.v): a simulator outside Rust
// confirms the frames the Rust tests check. The vector file, written from the bit-exact
// model by the test `raster_top_iverilog_replay` (testbenches/tests/raster_top.rs), holds
// a frame's triangles (the model's `Vtx` words) and the memory writes the model makes, in
// order; this bench sends the triangles back to back, keeps the depth buffer, and checks
// every write `raster_top` makes against the next expected one.
//
// Vector file (text, every count before what it counts; numbers in hex):
//   width height cull_back triangles
//   triangles lines: x y z r g b iw for v0, v1, v2 (21 numbers, two's complement)
//   writes
//   writes lines: address ({y, x}) depth rgb
//
// Usage: vvp <compiled bench> +vectors=<file> [+stall]
//   +stall: the memory is not ready one cycle in seven (mem$ready low).
// Prints "PASS <writes> writes, <cycles> cycles" and ends with $finish, or "FAIL ..." and
// ends with $fatal.
`timescale 1ns / 1ps
module raster_top_tb;
    localparam ADDR_BITS = 20;
    localparam MAX_TRIANGLES = 1 << 16;
    localparam MAX_WRITES = 1 << 20;

    reg clock = 0;
    always #5 clock = ~clock;

    // The frame.
    reg [10:0] width, height;
    reg cull_back;
    integer n_tri, n_wr;
    reg [17:0] tri_words [0:MAX_TRIANGLES * 21 - 1];
    reg [ADDR_BITS-1:0] exp_addr [0:MAX_WRITES - 1];
    reg [15:0] exp_z [0:MAX_WRITES - 1];
    reg [23:0] exp_rgb [0:MAX_WRITES - 1];

    // The depth buffer, cleared to z_max; read data the cycle after (read-first).
    reg [15:0] zmem [0:(1 << ADDR_BITS) - 1];
    reg [15:0] rd_z = 0;
    reg mem_ready = 1;

    // The DUT's inputs.
    reg inp_valid = 0, inp_last = 0;
    reg [15:0] v0_x, v0_y, v1_x, v1_y, v2_x, v2_y;
    reg [17:0] v0_z, v1_z, v2_z;
    reg [7:0] v0_r, v0_g, v0_b, v1_r, v1_g, v1_b, v2_r, v2_g, v2_b;
    reg [15:0] v0_iw, v1_iw, v2_iw;

    wire inp_ready, verdict_valid, rd_en, wr_en, done;
    wire [1:0] verdict_code;
    wire [5:0] verdict_outside;
    wire [ADDR_BITS-1:0] rd_addr, wr_addr;
    wire [15:0] wr_z;
    wire [23:0] wr_rgb;

    raster_top dut(
        .clock(clock), .width(width), .height(height), .cull_back(cull_back),
        .inp$valid(inp_valid), .inp$ready(inp_ready), .inp_last(inp_last),
        .inp$v0_x(v0_x), .inp$v0_y(v0_y), .inp$v0_z(v0_z), .inp$v0_c0(v0_r), .inp$v0_c1(v0_g), .inp$v0_c2(v0_b), .inp$v0_iw(v0_iw),
        .inp$v1_x(v1_x), .inp$v1_y(v1_y), .inp$v1_z(v1_z), .inp$v1_c0(v1_r), .inp$v1_c1(v1_g), .inp$v1_c2(v1_b), .inp$v1_iw(v1_iw),
        .inp$v2_x(v2_x), .inp$v2_y(v2_y), .inp$v2_z(v2_z), .inp$v2_c0(v2_r), .inp$v2_c1(v2_g), .inp$v2_c2(v2_b), .inp$v2_iw(v2_iw),
        .verdict$valid(verdict_valid), .verdict$code(verdict_code), .verdict$outside(verdict_outside),
        .mem$ready(mem_ready), .mem$rd_en(rd_en), .mem$rd_addr(rd_addr), .mem$rd_z(rd_z),
        .mem$wr_en(wr_en), .mem$wr_addr(wr_addr), .mem$wr_z(wr_z), .mem$wr_rgb(wr_rgb), .done(done)
    );

    // Triangle `t` onto the DUT's inputs (after the edge: non-blocking).
    task offer(input integer t);
        integer b;
        begin
            b = t * 21;
            {v0_x, v0_y, v0_z, v0_r, v0_g, v0_b, v0_iw} <= {tri_words[b][15:0], tri_words[b+1][15:0], tri_words[b+2],
                tri_words[b+3][7:0], tri_words[b+4][7:0], tri_words[b+5][7:0], tri_words[b+6][15:0]};
            {v1_x, v1_y, v1_z, v1_r, v1_g, v1_b, v1_iw} <= {tri_words[b+7][15:0], tri_words[b+8][15:0], tri_words[b+9],
                tri_words[b+10][7:0], tri_words[b+11][7:0], tri_words[b+12][7:0], tri_words[b+13][15:0]};
            {v2_x, v2_y, v2_z, v2_r, v2_g, v2_b, v2_iw} <= {tri_words[b+14][15:0], tri_words[b+15][15:0], tri_words[b+16],
                tri_words[b+17][7:0], tri_words[b+18][7:0], tri_words[b+19][7:0], tri_words[b+20][15:0]};
            inp_valid <= 1;
            inp_last <= (t == n_tri - 1);
        end
    endtask

    integer fd, i, k, next, written, cycle, stall;
    reg [8*512-1:0] path;
    initial begin
        if (!$value$plusargs("vectors=%s", path)) $fatal(1, "FAIL: no +vectors=<file>");
        stall = $test$plusargs("stall");
        fd = $fopen(path, "r");
        if (fd == 0) $fatal(1, "FAIL: cannot open %0s", path);
        if ($fscanf(fd, "%h %h %h %h\n", width, height, cull_back, n_tri) != 4) $fatal(1, "FAIL: bad header");
        if (n_tri < 1 || n_tri > MAX_TRIANGLES) $fatal(1, "FAIL: %0d triangles", n_tri);
        for (i = 0; i < n_tri * 21; i = i + 1)
            if ($fscanf(fd, "%h", tri_words[i]) != 1) $fatal(1, "FAIL: triangle word %0d", i);
        if ($fscanf(fd, "%h", n_wr) != 1 || n_wr > MAX_WRITES) $fatal(1, "FAIL: bad write count");
        for (i = 0; i < n_wr; i = i + 1)
            if ($fscanf(fd, "%h %h %h", exp_addr[i], exp_z[i], exp_rgb[i]) != 3) $fatal(1, "FAIL: write %0d", i);
        $fclose(fd);
        for (i = 0; i < (1 << ADDR_BITS); i = i + 1) zmem[i] = 16'hffff;
        next = 0;
        written = 0;
        cycle = 0;
        offer(0);
    end

    // One rising edge: the memory's read and write, the triangle hand-over, the checks.
    always @(posedge clock) begin
        if (mem_ready && rd_en) rd_z <= zmem[rd_addr];
        if (mem_ready && wr_en) begin
            if (written >= n_wr) $fatal(1, "FAIL: cycle %0d: write %0d, the model makes %0d", cycle, written, n_wr);
            if (wr_addr !== exp_addr[written] || wr_z !== exp_z[written] || wr_rgb !== exp_rgb[written])
                $fatal(1, "FAIL: cycle %0d: write %0d is %h %h %h, the model's %h %h %h", cycle, written,
                    wr_addr, wr_z, wr_rgb, exp_addr[written], exp_z[written], exp_rgb[written]);
            zmem[wr_addr] <= wr_z;
            written = written + 1;
        end
        if (inp_valid && inp_ready) begin
            next = next + 1;
            if (next < n_tri) offer(next);
            else inp_valid <= 0;
        end
        if (done && !inp_valid && next == n_tri) begin
            if (written != n_wr) $fatal(1, "FAIL: %0d writes, the model makes %0d", written, n_wr);
            $display("PASS %0d writes, %0d cycles", written, cycle);
            $finish;
        end
        cycle = cycle + 1;
        if (cycle > 50000000) $fatal(1, "FAIL: no done after %0d cycles", cycle);
        mem_ready <= !(stall && cycle % 7 == 3);
    end
endmodule
