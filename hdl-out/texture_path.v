

module texture_path(clock,inp$valid,inp$ready,inp$x,inp$y,inp$z,inp$rgb0,inp$rgb1,inp$rgb2,inp_new,tri$x0,tri$y0,tri$x1,tri$y1,tri$x2,tri$y2,tri$sq0,tri$sq1,tri$sq2,tri$tq0,tri$tq1,tri$tq2,tri$q0,tri$q1,tri$q2,tri$mant,tri$exp,tri_mode,state$ws,state$hs,state$levels,state$base,state$min_linear,state$mag_linear,state$mip,state$wrap_s,state$wrap_t,state$format,state$gaussian,state$env,inp_flush,out$valid,out$ready,out$x,out$y,out$z,out$rgb0,out$rgb1,out$rgb2,out$alpha,out$mode,mem$valid,mem$addr,mem$ack,mem$rvalid,mem$rdata,counters$hits,counters$misses,counters$fills,idle);
    
    // Module arguments
    input wire  clock;
    input wire  inp$valid;
    output reg  inp$ready;
    input wire  [9:0] inp$x;
    input wire  [9:0] inp$y;
    input wire  [15:0] inp$z;
    input wire  [7:0] inp$rgb0;
    input wire  [7:0] inp$rgb1;
    input wire  [7:0] inp$rgb2;
    input wire  inp_new;
    input wire  [15:0] tri$x0;
    input wire  [15:0] tri$y0;
    input wire  [15:0] tri$x1;
    input wire  [15:0] tri$y1;
    input wire  [15:0] tri$x2;
    input wire  [15:0] tri$y2;
    input wire  [28:0] tri$sq0;
    input wire  [28:0] tri$sq1;
    input wire  [28:0] tri$sq2;
    input wire  [28:0] tri$tq0;
    input wire  [28:0] tri$tq1;
    input wire  [28:0] tri$tq2;
    input wire  [20:0] tri$q0;
    input wire  [20:0] tri$q1;
    input wire  [20:0] tri$q2;
    input wire  [24:0] tri$mant;
    input wire  [5:0] tri$exp;
    input wire  [2:0] tri_mode;
    input wire  [3:0] state$ws;
    input wire  [3:0] state$hs;
    input wire  [3:0] state$levels;
    input wire  [25:0] state$base;
    input wire  state$min_linear;
    input wire  state$mag_linear;
    input wire  [1:0] state$mip;
    input wire  [1:0] state$wrap_s;
    input wire  [1:0] state$wrap_t;
    input wire  [2:0] state$format;
    input wire  state$gaussian;
    input wire  [2:0] state$env;
    input wire  inp_flush;
    output reg  out$valid;
    input wire  out$ready;
    output reg  [9:0] out$x;
    output reg  [9:0] out$y;
    output reg  [15:0] out$z;
    output reg  [7:0] out$rgb0;
    output reg  [7:0] out$rgb1;
    output reg  [7:0] out$rgb2;
    output reg  [7:0] out$alpha;
    output reg  [2:0] out$mode;
    output wire  mem$valid;
    output wire  [25:0] mem$addr;
    input wire  mem$ack;
    input wire  mem$rvalid;
    input wire  [31:0] mem$rdata;
    output wire  [31:0] counters$hits;
    output wire  [31:0] counters$misses;
    output wire  [31:0] counters$fills;
    output reg  idle;
    
    // Constant declarations
    localparam  run = 2'b0;
    localparam  drain = 2'b1;
    localparam  setup_phase = 2'b10;
    localparam  first = 2'b11;
    localparam  at_x = 8'h1d;
    localparam  at_y = 8'h13;
    localparam  at_z = 8'h3;
    
    // Stub signals
    reg  setup$clock;
    reg  setup$start;
    wire  setup$done;
    wire  [32:0] setup$dsq_x;
    wire  [32:0] setup$dsq_y;
    wire  [32:0] setup$dtq_x;
    wire  [32:0] setup$dtq_y;
    wire  [29:0] setup$dq_x;
    wire  [29:0] setup$dq_y;
    reg  setup$en;
    reg  setup$inp_valid;
    reg  [9:0] setup$inp_x;
    reg  [9:0] setup$inp_y;
    wire  setup$out_valid;
    wire  [28:0] setup$out_sq;
    wire  [28:0] setup$out_tq;
    wire  [20:0] setup$out_q;
    reg  unit$clock;
    reg  unit$inp_valid;
    wire  unit$inp_ready;
    reg  [28:0] unit$inp_sq;
    reg  [28:0] unit$inp_tq;
    reg  [20:0] unit$inp_q;
    reg  [32:0] unit$inp_dsq_x;
    reg  [32:0] unit$inp_dsq_y;
    reg  [32:0] unit$inp_dtq_x;
    reg  [32:0] unit$inp_dtq_y;
    reg  [29:0] unit$inp_dq_x;
    reg  [29:0] unit$inp_dq_y;
    reg  [23:0] unit$inp_cf;
    reg  [31:0] unit$inp_tag;
    reg  unit$st_load;
    reg  unit$inp_flush;
    wire  unit$out_valid;
    reg  unit$out_ready;
    wire  [31:0] unit$out_rgba;
    wire  [31:0] unit$out_tag;
    wire  unit$idle;
    reg  [5:0] side$read_address;
    reg  side$read_clock;
    wire  [38:0] side$read_data;
    reg  [5:0] side$write_address;
    reg  side$write_clock;
    reg  [38:0] side$write_data;
    reg  side$write_enable;
    reg  [1:0] phase$d;
    wire  [1:0] phase$q;
    reg  phase$clock;
    reg  [52:0] loaded$d;
    wire  [52:0] loaded$q;
    reg  loaded$clock;
    reg  [1:0] in_px$d;
    wire  [1:0] in_px$q;
    reg  in_px$clock;
    reg  [23:0] cf$0$d;
    wire  [23:0] cf$0$q;
    reg  cf$0$clock;
    reg  [23:0] cf$1$d;
    wire  [23:0] cf$1$q;
    reg  cf$1$clock;
    reg  [23:0] cf$2$d;
    wire  [23:0] cf$2$q;
    reg  cf$2$clock;
    reg  [5:0] wp$d;
    wire  [5:0] wp$q;
    reg  wp$clock;
    reg  [5:0] rt$d;
    wire  [5:0] rt$q;
    reg  rt$clock;
    
    // Local signals
    reg  [52:0] st_word;
    reg  same;
    reg  start;
    reg  en;
    reg  accept;
    reg  leave;
    reg  [38:0] side_in;
    
    // Sub module instances
    texture_path$setup setup(
        .clock(setup$clock),
        .start(setup$start),
        .tri$x0(tri$x0),
        .tri$y0(tri$y0),
        .tri$x1(tri$x1),
        .tri$y1(tri$y1),
        .tri$x2(tri$x2),
        .tri$y2(tri$y2),
        .tri$sq0(tri$sq0),
        .tri$sq1(tri$sq1),
        .tri$sq2(tri$sq2),
        .tri$tq0(tri$tq0),
        .tri$tq1(tri$tq1),
        .tri$tq2(tri$tq2),
        .tri$q0(tri$q0),
        .tri$q1(tri$q1),
        .tri$q2(tri$q2),
        .tri$mant(tri$mant),
        .tri$exp(tri$exp),
        .done(setup$done),
        .dsq_x(setup$dsq_x),
        .dsq_y(setup$dsq_y),
        .dtq_x(setup$dtq_x),
        .dtq_y(setup$dtq_y),
        .dq_x(setup$dq_x),
        .dq_y(setup$dq_y),
        .en(setup$en),
        .inp_valid(setup$inp_valid),
        .inp_x(setup$inp_x),
        .inp_y(setup$inp_y),
        .out_valid(setup$out_valid),
        .out_sq(setup$out_sq),
        .out_tq(setup$out_tq),
        .out_q(setup$out_q)
    );
    texture_path$unit unit(
        .clock(unit$clock),
        .inp_valid(unit$inp_valid),
        .inp_ready(unit$inp_ready),
        .inp_sq(unit$inp_sq),
        .inp_tq(unit$inp_tq),
        .inp_q(unit$inp_q),
        .inp_dsq_x(unit$inp_dsq_x),
        .inp_dsq_y(unit$inp_dsq_y),
        .inp_dtq_x(unit$inp_dtq_x),
        .inp_dtq_y(unit$inp_dtq_y),
        .inp_dq_x(unit$inp_dq_x),
        .inp_dq_y(unit$inp_dq_y),
        .inp_cf(unit$inp_cf),
        .inp_tag(unit$inp_tag),
        .st_load(unit$st_load),
        .st$ws(state$ws),
        .st$hs(state$hs),
        .st$levels(state$levels),
        .st$base(state$base),
        .st$min_linear(state$min_linear),
        .st$mag_linear(state$mag_linear),
        .st$mip(state$mip),
        .st$wrap_s(state$wrap_s),
        .st$wrap_t(state$wrap_t),
        .st$format(state$format),
        .st$gaussian(state$gaussian),
        .st$env(state$env),
        .inp_flush(unit$inp_flush),
        .out_valid(unit$out_valid),
        .out_ready(unit$out_ready),
        .out_rgba(unit$out_rgba),
        .out_tag(unit$out_tag),
        .mem$valid(mem$valid),
        .mem$addr(mem$addr),
        .mem$ack(mem$ack),
        .mem$rvalid(mem$rvalid),
        .mem$rdata(mem$rdata),
        .counters$hits(counters$hits),
        .counters$misses(counters$misses),
        .counters$fills(counters$fills),
        .idle(unit$idle)
    );
    texture_path$side side(
        .read_address(side$read_address),
        .read_clock(side$read_clock),
        .read_data(side$read_data),
        .write_address(side$write_address),
        .write_clock(side$write_clock),
        .write_data(side$write_data),
        .write_enable(side$write_enable)
    );
    texture_path$phase phase(
        .d(phase$d),
        .q(phase$q),
        .clock(phase$clock)
    );
    texture_path$loaded loaded(
        .d(loaded$d),
        .q(loaded$q),
        .clock(loaded$clock)
    );
    texture_path$in_px in_px(
        .d(in_px$d),
        .q(in_px$q),
        .clock(in_px$clock)
    );
    texture_path$cf$0 cf$0(
        .d(cf$0$d),
        .q(cf$0$q),
        .clock(cf$0$clock)
    );
    texture_path$cf$1 cf$1(
        .d(cf$1$d),
        .q(cf$1$q),
        .clock(cf$1$clock)
    );
    texture_path$cf$2 cf$2(
        .d(cf$2$d),
        .q(cf$2$q),
        .clock(cf$2$clock)
    );
    texture_path$wp wp(
        .d(wp$d),
        .q(wp$q),
        .clock(wp$clock)
    );
    texture_path$rt rt(
        .d(rt$d),
        .q(rt$q),
        .clock(rt$clock)
    );
    
    // Update code
    always @(*) begin
        phase$clock = clock;
        loaded$clock = clock;
        in_px$clock = clock;
        wp$clock = clock;
        rt$clock = clock;
        phase$d = phase$q;
        loaded$d = loaded$q;
        in_px$d = in_px$q;
        wp$d = wp$q;
        rt$d = rt$q;
        cf$0$clock = clock;
        cf$0$d = cf$0$q;
        cf$1$clock = clock;
        cf$1$d = cf$1$q;
        cf$2$clock = clock;
        cf$2$d = cf$2$q;
        setup$clock = clock;
        unit$clock = clock;
        st_word = (((state$ws) & 53'h1fffffffffffff) << 32'h31) | (((state$hs) & 53'h1fffffffffffff) << 32'h2d) | (((state$levels) & 53'h1fffffffffffff) << 32'h29) | (((state$base) & 53'h1fffffffffffff) << 32'hf) | (((state$mip) & 53'h1fffffffffffff) << 32'hb) | (((state$wrap_s) & 53'h1fffffffffffff) << 32'h9) | (((state$wrap_t) & 53'h1fffffffffffff) << 32'h7) | (((state$format) & 53'h1fffffffffffff) << 32'h4) | ((state$env) & 53'h1fffffffffffff);
        if (state$min_linear) begin
            st_word = (st_word & ~(1 << (32'he)) | ((1'b1) << (32'he)));
        end
        if (state$mag_linear) begin
            st_word = (st_word & ~(1 << (32'hd)) | ((1'b1) << (32'hd)));
        end
        if (state$gaussian) begin
            st_word = (st_word & ~(1 << (32'h3)) | ((1'b1) << (32'h3)));
        end
        same = st_word == loaded$q;
        start = (phase$q == drain) & (in_px$q == 32'h0) & (same | unit$idle);
        setup$start = start;
        unit$inp_valid = setup$out_valid;
        unit$inp_sq = setup$out_sq;
        unit$inp_tq = setup$out_tq;
        unit$inp_q = setup$out_q;
        unit$inp_dsq_x = setup$dsq_x;
        unit$inp_dsq_y = setup$dsq_y;
        unit$inp_dtq_x = setup$dtq_x;
        unit$inp_dtq_y = setup$dtq_y;
        unit$inp_dq_x = setup$dq_x;
        unit$inp_dq_y = setup$dq_y;
        unit$inp_cf = cf$2$q;
        unit$inp_tag = 32'h0;
        unit$st_load = start & ~same;
        unit$inp_flush = inp_flush;
        unit$out_ready = out$ready;
        en = ~setup$out_valid | unit$inp_ready;
        inp$ready = en & (((phase$q == run) & ~inp_new) | (phase$q == first));
        accept = inp$valid & inp$ready;
        setup$en = en;
        setup$inp_valid = accept;
        setup$inp_x = inp$x;
        setup$inp_y = inp$y;
        if (en) begin
            cf$0$d = (((inp$rgb0) & 24'hffffff) << 32'h10) | (((inp$rgb1) & 24'hffffff) << 32'h8) | ((inp$rgb2) & 24'hffffff);
            cf$1$d = cf$0$q;
            cf$2$d = cf$1$q;
        end
        leave = setup$out_valid & unit$inp_ready;
        if (accept & ~leave) begin
            in_px$d = in_px$q + 32'h1;
        end
        if (~accept & leave) begin
            in_px$d = in_px$q - 32'h1;
        end
        if ((phase$q == run) & inp$valid & inp_new) begin
            phase$d = drain;
        end
        if (start) begin
            phase$d = setup_phase;
            loaded$d = st_word;
        end
        if ((phase$q == setup_phase) & setup$done) begin
            phase$d = first;
        end
        if ((phase$q == first) & accept) begin
            phase$d = run;
        end
        side_in = (((inp$x) & 39'h7fffffffff) << at_x) | (((inp$y) & 39'h7fffffffff) << at_y) | (((inp$z) & 39'h7fffffffff) << at_z) | ((tri_mode) & 39'h7fffffffff);
        side$write_clock = clock;
        side$read_clock = clock;
        side$write_enable = accept;
        side$write_address = wp$q;
        side$write_data = side_in;
        if (accept) begin
            wp$d = wp$q + 32'h1;
        end
        side$read_address = rt$q;
        if (unit$out_valid & out$ready) begin
            rt$d = rt$q + 32'h1;
            side$read_address = rt$q + 32'h1;
        end
        out$valid = unit$out_valid;
        out$x = side$read_data[(at_x)+:(10)];
        out$y = side$read_data[(at_y)+:(10)];
        out$z = side$read_data[(at_z)+:(16)];
        out$mode = side$read_data[(32'h0)+:(3)];
        out$rgb0 = unit$out_rgba[(32'h18)+:(8)];
        out$rgb1 = unit$out_rgba[(32'h10)+:(8)];
        out$rgb2 = unit$out_rgba[(32'h8)+:(8)];
        out$alpha = unit$out_rgba[(32'h0)+:(8)];
        idle = unit$idle & (in_px$q == 32'h0) & (phase$q == run);
    end
    
endmodule // texture_path


module texture_path$cf$0(d,q,clock);
    
    // Module arguments
    input wire  [23:0] d;
    output reg  [23:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 24'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$cf$0


module texture_path$cf$1(d,q,clock);
    
    // Module arguments
    input wire  [23:0] d;
    output reg  [23:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 24'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$cf$1


module texture_path$cf$2(d,q,clock);
    
    // Module arguments
    input wire  [23:0] d;
    output reg  [23:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 24'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$cf$2


module texture_path$in_px(d,q,clock);
    
    // Module arguments
    input wire  [1:0] d;
    output reg  [1:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 2'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$in_px


module texture_path$loaded(d,q,clock);
    
    // Module arguments
    input wire  [52:0] d;
    output reg  [52:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 53'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$loaded


module texture_path$phase(d,q,clock);
    
    // Module arguments
    input wire  [1:0] d;
    output reg  [1:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 2'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$phase


module texture_path$rt(d,q,clock);
    
    // Module arguments
    input wire  [5:0] d;
    output reg  [5:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 6'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$rt


module texture_path$setup(clock,start,tri$x0,tri$y0,tri$x1,tri$y1,tri$x2,tri$y2,tri$sq0,tri$sq1,tri$sq2,tri$tq0,tri$tq1,tri$tq2,tri$q0,tri$q1,tri$q2,tri$mant,tri$exp,done,dsq_x,dsq_y,dtq_x,dtq_y,dq_x,dq_y,en,inp_valid,inp_x,inp_y,out_valid,out_sq,out_tq,out_q);
    
    // Module arguments
    input wire  clock;
    input wire  start;
    input wire  [15:0] tri$x0;
    input wire  [15:0] tri$y0;
    input wire  [15:0] tri$x1;
    input wire  [15:0] tri$y1;
    input wire  [15:0] tri$x2;
    input wire  [15:0] tri$y2;
    input wire  [28:0] tri$sq0;
    input wire  [28:0] tri$sq1;
    input wire  [28:0] tri$sq2;
    input wire  [28:0] tri$tq0;
    input wire  [28:0] tri$tq1;
    input wire  [28:0] tri$tq2;
    input wire  [20:0] tri$q0;
    input wire  [20:0] tri$q1;
    input wire  [20:0] tri$q2;
    input wire  [24:0] tri$mant;
    input wire  [5:0] tri$exp;
    output reg  done;
    output reg  [32:0] dsq_x;
    output reg  [32:0] dsq_y;
    output reg  [32:0] dtq_x;
    output reg  [32:0] dtq_y;
    output reg  [29:0] dq_x;
    output reg  [29:0] dq_y;
    input wire  en;
    input wire  inp_valid;
    input wire  [9:0] inp_x;
    input wire  [9:0] inp_y;
    output reg  out_valid;
    output reg  [28:0] out_sq;
    output reg  [28:0] out_tq;
    output reg  [20:0] out_q;
    
    // Constant declarations
    localparam  pre = 7'b110;
    localparam  mp_msb = 8'h49;
    localparam  mp_top = 74'h2000000000000000000;
    localparam  half_st = 74'h100;
    localparam  sh_st = 8'h9;
    localparam  bias_st = 74'h20000000000;
    localparam  lim_st = 74'h40000000000;
    localparam  max_st = 33'hffffffff;
    localparam  min_st = 33'h100000000;
    localparam  half_q = 74'h10;
    localparam  sh_q = 8'h5;
    localparam  bias_q = 74'h400000000;
    localparam  lim_q = 74'h800000000;
    localparam  max_q = 30'h1fffffff;
    localparam  min_q = 30'h20000000;
    localparam  sub = 8'h4;
    localparam  centre = 18'b1000;
    localparam  rs = 8'h11;
    localparam  half_f = 47'h10000;
    localparam  ws_msb = 8'h1d;
    localparam  ws_top = 8'h1c;
    localparam  wq_msb = 8'h16;
    localparam  wq_top = 8'h15;
    localparam  st_max = 29'hfffffff;
    localparam  st_min = 29'h10000000;
    localparam  q_max = 21'h1fffff;
    
    // Stub signals
    reg  [4:0] step$d;
    wire  [4:0] step$q;
    reg  step$clock;
    reg  busy$d;
    wire  busy$q;
    reg  busy$clock;
    reg  done_r$d;
    wire  done_r$q;
    reg  done_r$clock;
    reg  neg$d;
    wire  neg$q;
    reg  neg$clock;
    reg  [15:0] sx_pos$0$x;
    wire  [25:0] sx_pos$0$y;
    reg  [15:0] sx_pos$1$x;
    wire  [25:0] sx_pos$1$y;
    reg  [15:0] sx_pos$2$x;
    wire  [25:0] sx_pos$2$y;
    reg  [15:0] sx_pos$3$x;
    wire  [25:0] sx_pos$3$y;
    reg  [15:0] sx_pos$4$x;
    wire  [25:0] sx_pos$4$y;
    reg  [15:0] sx_pos$5$x;
    wire  [25:0] sx_pos$5$y;
    reg  [28:0] sx_st$0$x;
    wire  [29:0] sx_st$0$y;
    reg  [28:0] sx_st$1$x;
    wire  [29:0] sx_st$1$y;
    reg  [28:0] sx_st$2$x;
    wire  [29:0] sx_st$2$y;
    reg  [28:0] sx_st$3$x;
    wire  [29:0] sx_st$3$y;
    reg  [28:0] sx_st$4$x;
    wire  [29:0] sx_st$4$y;
    reg  [28:0] sx_st$5$x;
    wire  [29:0] sx_st$5$y;
    reg  [25:0] e1x$d;
    wire  [25:0] e1x$q;
    reg  e1x$clock;
    reg  [25:0] e1y$d;
    wire  [25:0] e1y$q;
    reg  e1y$clock;
    reg  [25:0] e2x$d;
    wire  [25:0] e2x$q;
    reg  e2x$clock;
    reg  [25:0] e2y$d;
    wire  [25:0] e2y$q;
    reg  e2y$clock;
    reg  [25:0] sx_e1x$x;
    wire  [47:0] sx_e1x$y;
    reg  [25:0] sx_e2x$x;
    wire  [47:0] sx_e2x$y;
    reg  [29:0] d1$0$d;
    wire  [29:0] d1$0$q;
    reg  d1$0$clock;
    reg  [29:0] d1$1$d;
    wire  [29:0] d1$1$q;
    reg  d1$1$clock;
    reg  [29:0] d1$2$d;
    wire  [29:0] d1$2$q;
    reg  d1$2$clock;
    reg  [29:0] d2$0$d;
    wire  [29:0] d2$0$q;
    reg  d2$0$clock;
    reg  [29:0] d2$1$d;
    wire  [29:0] d2$1$q;
    reg  d2$1$clock;
    reg  [29:0] d2$2$d;
    wire  [29:0] d2$2$q;
    reg  d2$2$clock;
    reg  [29:0] sx_d$x;
    wire  [47:0] sx_d$y;
    reg  [24:0] mant$d;
    wire  [24:0] mant$q;
    reg  mant$clock;
    reg  [5:0] exp$d;
    wire  [5:0] exp$q;
    reg  exp$clock;
    reg  [47:0] mul$a;
    reg  [25:0] mul$b;
    wire  [73:0] mul$p;
    reg  [73:0] prod$d;
    wire  [73:0] prod$q;
    reg  prod$clock;
    reg  [73:0] acc$d;
    wire  [73:0] acc$q;
    reg  acc$clock;
    reg  [17:0] ox$d;
    wire  [17:0] ox$q;
    reg  ox$clock;
    reg  [17:0] oy$d;
    wire  [17:0] oy$q;
    reg  oy$clock;
    reg  [46:0] a0_sq$d;
    wire  [46:0] a0_sq$q;
    reg  a0_sq$clock;
    reg  [46:0] a0_tq$d;
    wire  [46:0] a0_tq$q;
    reg  a0_tq$clock;
    reg  [39:0] a0_q$d;
    wire  [39:0] a0_q$q;
    reg  a0_q$clock;
    reg  [46:0] g_sq$0$d;
    wire  [46:0] g_sq$0$q;
    reg  g_sq$0$clock;
    reg  [46:0] g_sq$1$d;
    wire  [46:0] g_sq$1$q;
    reg  g_sq$1$clock;
    reg  [46:0] g_tq$0$d;
    wire  [46:0] g_tq$0$q;
    reg  g_tq$0$clock;
    reg  [46:0] g_tq$1$d;
    wire  [46:0] g_tq$1$q;
    reg  g_tq$1$clock;
    reg  [39:0] g_q$0$d;
    wire  [39:0] g_q$0$q;
    reg  g_q$0$clock;
    reg  [39:0] g_q$1$d;
    wire  [39:0] g_q$1$q;
    reg  g_q$1$clock;
    reg  [32:0] lod_sq$0$d;
    wire  [32:0] lod_sq$0$q;
    reg  lod_sq$0$clock;
    reg  [32:0] lod_sq$1$d;
    wire  [32:0] lod_sq$1$q;
    reg  lod_sq$1$clock;
    reg  [32:0] lod_tq$0$d;
    wire  [32:0] lod_tq$0$q;
    reg  lod_tq$0$clock;
    reg  [32:0] lod_tq$1$d;
    wire  [32:0] lod_tq$1$q;
    reg  lod_tq$1$clock;
    reg  [29:0] lod_q$0$d;
    wire  [29:0] lod_q$0$q;
    reg  lod_q$0$clock;
    reg  [29:0] lod_q$1$d;
    wire  [29:0] lod_q$1$q;
    reg  lod_q$1$clock;
    reg  s1_valid$d;
    wire  s1_valid$q;
    reg  s1_valid$clock;
    reg  [17:0] s1_x$d;
    wire  [17:0] s1_x$q;
    reg  s1_x$clock;
    reg  [17:0] s1_y$d;
    wire  [17:0] s1_y$q;
    reg  s1_y$clock;
    reg  [46:0] mul_sq$0$a;
    reg  [17:0] mul_sq$0$b;
    wire  [46:0] mul_sq$0$p;
    reg  [46:0] mul_sq$1$a;
    reg  [17:0] mul_sq$1$b;
    wire  [46:0] mul_sq$1$p;
    reg  [46:0] mul_tq$0$a;
    reg  [17:0] mul_tq$0$b;
    wire  [46:0] mul_tq$0$p;
    reg  [46:0] mul_tq$1$a;
    reg  [17:0] mul_tq$1$b;
    wire  [46:0] mul_tq$1$p;
    reg  [39:0] mul_q$0$a;
    reg  [17:0] mul_q$0$b;
    wire  [39:0] mul_q$0$p;
    reg  [39:0] mul_q$1$a;
    reg  [17:0] mul_q$1$b;
    wire  [39:0] mul_q$1$p;
    reg  s2_valid$d;
    wire  s2_valid$q;
    reg  s2_valid$clock;
    reg  [46:0] s2_sq$0$d;
    wire  [46:0] s2_sq$0$q;
    reg  s2_sq$0$clock;
    reg  [46:0] s2_sq$1$d;
    wire  [46:0] s2_sq$1$q;
    reg  s2_sq$1$clock;
    reg  [46:0] s2_tq$0$d;
    wire  [46:0] s2_tq$0$q;
    reg  s2_tq$0$clock;
    reg  [46:0] s2_tq$1$d;
    wire  [46:0] s2_tq$1$q;
    reg  s2_tq$1$clock;
    reg  [39:0] s2_q$0$d;
    wire  [39:0] s2_q$0$q;
    reg  s2_q$0$clock;
    reg  [39:0] s2_q$1$d;
    wire  [39:0] s2_q$1$q;
    reg  s2_q$1$clock;
    reg  s3_valid$d;
    wire  s3_valid$q;
    reg  s3_valid$clock;
    reg  [28:0] s3_sq$d;
    wire  [28:0] s3_sq$q;
    reg  s3_sq$clock;
    reg  [28:0] s3_tq$d;
    wire  [28:0] s3_tq$q;
    reg  s3_tq$clock;
    reg  [20:0] s3_q$d;
    wire  [20:0] s3_q$q;
    reg  s3_q$clock;
    
    // Local signals
    reg  [29:0] sel_d;
    reg  [47:0] mul_a;
    reg  [25:0] mul_b;
    reg  [6:0] k1;
    reg  [73:0] zs;
    reg  [73:0] y1;
    reg  [73:0] exact;
    reg  [73:0] t_st;
    reg  [73:0] u_st;
    reg  [73:0] ts_st;
    reg  [32:0] l_st;
    reg  [73:0] t_q;
    reg  [73:0] u_q;
    reg  [73:0] ts_q;
    reg  [29:0] l_q;
    reg  [46:0] sum_sq;
    reg  [46:0] sum_tq;
    reg  [39:0] sum_q;
    reg  [29:0] w_sq;
    reg  [29:0] w_tq;
    reg  [22:0] w_q;
    
    // Sub module instances
    texture_path$setup$step step(
        .d(step$d),
        .q(step$q),
        .clock(step$clock)
    );
    texture_path$setup$busy busy(
        .d(busy$d),
        .q(busy$q),
        .clock(busy$clock)
    );
    texture_path$setup$done_r done_r(
        .d(done_r$d),
        .q(done_r$q),
        .clock(done_r$clock)
    );
    texture_path$setup$neg neg(
        .d(neg$d),
        .q(neg$q),
        .clock(neg$clock)
    );
    texture_path$setup$sx_pos$0 sx_pos$0(
        .x(sx_pos$0$x),
        .y(sx_pos$0$y)
    );
    texture_path$setup$sx_pos$1 sx_pos$1(
        .x(sx_pos$1$x),
        .y(sx_pos$1$y)
    );
    texture_path$setup$sx_pos$2 sx_pos$2(
        .x(sx_pos$2$x),
        .y(sx_pos$2$y)
    );
    texture_path$setup$sx_pos$3 sx_pos$3(
        .x(sx_pos$3$x),
        .y(sx_pos$3$y)
    );
    texture_path$setup$sx_pos$4 sx_pos$4(
        .x(sx_pos$4$x),
        .y(sx_pos$4$y)
    );
    texture_path$setup$sx_pos$5 sx_pos$5(
        .x(sx_pos$5$x),
        .y(sx_pos$5$y)
    );
    texture_path$setup$sx_st$0 sx_st$0(
        .x(sx_st$0$x),
        .y(sx_st$0$y)
    );
    texture_path$setup$sx_st$1 sx_st$1(
        .x(sx_st$1$x),
        .y(sx_st$1$y)
    );
    texture_path$setup$sx_st$2 sx_st$2(
        .x(sx_st$2$x),
        .y(sx_st$2$y)
    );
    texture_path$setup$sx_st$3 sx_st$3(
        .x(sx_st$3$x),
        .y(sx_st$3$y)
    );
    texture_path$setup$sx_st$4 sx_st$4(
        .x(sx_st$4$x),
        .y(sx_st$4$y)
    );
    texture_path$setup$sx_st$5 sx_st$5(
        .x(sx_st$5$x),
        .y(sx_st$5$y)
    );
    texture_path$setup$e1x e1x(
        .d(e1x$d),
        .q(e1x$q),
        .clock(e1x$clock)
    );
    texture_path$setup$e1y e1y(
        .d(e1y$d),
        .q(e1y$q),
        .clock(e1y$clock)
    );
    texture_path$setup$e2x e2x(
        .d(e2x$d),
        .q(e2x$q),
        .clock(e2x$clock)
    );
    texture_path$setup$e2y e2y(
        .d(e2y$d),
        .q(e2y$q),
        .clock(e2y$clock)
    );
    texture_path$setup$sx_e1x sx_e1x(
        .x(sx_e1x$x),
        .y(sx_e1x$y)
    );
    texture_path$setup$sx_e2x sx_e2x(
        .x(sx_e2x$x),
        .y(sx_e2x$y)
    );
    texture_path$setup$d1$0 d1$0(
        .d(d1$0$d),
        .q(d1$0$q),
        .clock(d1$0$clock)
    );
    texture_path$setup$d1$1 d1$1(
        .d(d1$1$d),
        .q(d1$1$q),
        .clock(d1$1$clock)
    );
    texture_path$setup$d1$2 d1$2(
        .d(d1$2$d),
        .q(d1$2$q),
        .clock(d1$2$clock)
    );
    texture_path$setup$d2$0 d2$0(
        .d(d2$0$d),
        .q(d2$0$q),
        .clock(d2$0$clock)
    );
    texture_path$setup$d2$1 d2$1(
        .d(d2$1$d),
        .q(d2$1$q),
        .clock(d2$1$clock)
    );
    texture_path$setup$d2$2 d2$2(
        .d(d2$2$d),
        .q(d2$2$q),
        .clock(d2$2$clock)
    );
    texture_path$setup$sx_d sx_d(
        .x(sx_d$x),
        .y(sx_d$y)
    );
    texture_path$setup$mant mant(
        .d(mant$d),
        .q(mant$q),
        .clock(mant$clock)
    );
    texture_path$setup$exp exp(
        .d(exp$d),
        .q(exp$q),
        .clock(exp$clock)
    );
    texture_path$setup$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    texture_path$setup$prod prod(
        .d(prod$d),
        .q(prod$q),
        .clock(prod$clock)
    );
    texture_path$setup$acc acc(
        .d(acc$d),
        .q(acc$q),
        .clock(acc$clock)
    );
    texture_path$setup$ox ox(
        .d(ox$d),
        .q(ox$q),
        .clock(ox$clock)
    );
    texture_path$setup$oy oy(
        .d(oy$d),
        .q(oy$q),
        .clock(oy$clock)
    );
    texture_path$setup$a0_sq a0_sq(
        .d(a0_sq$d),
        .q(a0_sq$q),
        .clock(a0_sq$clock)
    );
    texture_path$setup$a0_tq a0_tq(
        .d(a0_tq$d),
        .q(a0_tq$q),
        .clock(a0_tq$clock)
    );
    texture_path$setup$a0_q a0_q(
        .d(a0_q$d),
        .q(a0_q$q),
        .clock(a0_q$clock)
    );
    texture_path$setup$g_sq$0 g_sq$0(
        .d(g_sq$0$d),
        .q(g_sq$0$q),
        .clock(g_sq$0$clock)
    );
    texture_path$setup$g_sq$1 g_sq$1(
        .d(g_sq$1$d),
        .q(g_sq$1$q),
        .clock(g_sq$1$clock)
    );
    texture_path$setup$g_tq$0 g_tq$0(
        .d(g_tq$0$d),
        .q(g_tq$0$q),
        .clock(g_tq$0$clock)
    );
    texture_path$setup$g_tq$1 g_tq$1(
        .d(g_tq$1$d),
        .q(g_tq$1$q),
        .clock(g_tq$1$clock)
    );
    texture_path$setup$g_q$0 g_q$0(
        .d(g_q$0$d),
        .q(g_q$0$q),
        .clock(g_q$0$clock)
    );
    texture_path$setup$g_q$1 g_q$1(
        .d(g_q$1$d),
        .q(g_q$1$q),
        .clock(g_q$1$clock)
    );
    texture_path$setup$lod_sq$0 lod_sq$0(
        .d(lod_sq$0$d),
        .q(lod_sq$0$q),
        .clock(lod_sq$0$clock)
    );
    texture_path$setup$lod_sq$1 lod_sq$1(
        .d(lod_sq$1$d),
        .q(lod_sq$1$q),
        .clock(lod_sq$1$clock)
    );
    texture_path$setup$lod_tq$0 lod_tq$0(
        .d(lod_tq$0$d),
        .q(lod_tq$0$q),
        .clock(lod_tq$0$clock)
    );
    texture_path$setup$lod_tq$1 lod_tq$1(
        .d(lod_tq$1$d),
        .q(lod_tq$1$q),
        .clock(lod_tq$1$clock)
    );
    texture_path$setup$lod_q$0 lod_q$0(
        .d(lod_q$0$d),
        .q(lod_q$0$q),
        .clock(lod_q$0$clock)
    );
    texture_path$setup$lod_q$1 lod_q$1(
        .d(lod_q$1$d),
        .q(lod_q$1$q),
        .clock(lod_q$1$clock)
    );
    texture_path$setup$s1_valid s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    texture_path$setup$s1_x s1_x(
        .d(s1_x$d),
        .q(s1_x$q),
        .clock(s1_x$clock)
    );
    texture_path$setup$s1_y s1_y(
        .d(s1_y$d),
        .q(s1_y$q),
        .clock(s1_y$clock)
    );
    texture_path$setup$mul_sq$0 mul_sq$0(
        .a(mul_sq$0$a),
        .b(mul_sq$0$b),
        .p(mul_sq$0$p)
    );
    texture_path$setup$mul_sq$1 mul_sq$1(
        .a(mul_sq$1$a),
        .b(mul_sq$1$b),
        .p(mul_sq$1$p)
    );
    texture_path$setup$mul_tq$0 mul_tq$0(
        .a(mul_tq$0$a),
        .b(mul_tq$0$b),
        .p(mul_tq$0$p)
    );
    texture_path$setup$mul_tq$1 mul_tq$1(
        .a(mul_tq$1$a),
        .b(mul_tq$1$b),
        .p(mul_tq$1$p)
    );
    texture_path$setup$mul_q$0 mul_q$0(
        .a(mul_q$0$a),
        .b(mul_q$0$b),
        .p(mul_q$0$p)
    );
    texture_path$setup$mul_q$1 mul_q$1(
        .a(mul_q$1$a),
        .b(mul_q$1$b),
        .p(mul_q$1$p)
    );
    texture_path$setup$s2_valid s2_valid(
        .d(s2_valid$d),
        .q(s2_valid$q),
        .clock(s2_valid$clock)
    );
    texture_path$setup$s2_sq$0 s2_sq$0(
        .d(s2_sq$0$d),
        .q(s2_sq$0$q),
        .clock(s2_sq$0$clock)
    );
    texture_path$setup$s2_sq$1 s2_sq$1(
        .d(s2_sq$1$d),
        .q(s2_sq$1$q),
        .clock(s2_sq$1$clock)
    );
    texture_path$setup$s2_tq$0 s2_tq$0(
        .d(s2_tq$0$d),
        .q(s2_tq$0$q),
        .clock(s2_tq$0$clock)
    );
    texture_path$setup$s2_tq$1 s2_tq$1(
        .d(s2_tq$1$d),
        .q(s2_tq$1$q),
        .clock(s2_tq$1$clock)
    );
    texture_path$setup$s2_q$0 s2_q$0(
        .d(s2_q$0$d),
        .q(s2_q$0$q),
        .clock(s2_q$0$clock)
    );
    texture_path$setup$s2_q$1 s2_q$1(
        .d(s2_q$1$d),
        .q(s2_q$1$q),
        .clock(s2_q$1$clock)
    );
    texture_path$setup$s3_valid s3_valid(
        .d(s3_valid$d),
        .q(s3_valid$q),
        .clock(s3_valid$clock)
    );
    texture_path$setup$s3_sq s3_sq(
        .d(s3_sq$d),
        .q(s3_sq$q),
        .clock(s3_sq$clock)
    );
    texture_path$setup$s3_tq s3_tq(
        .d(s3_tq$d),
        .q(s3_tq$q),
        .clock(s3_tq$clock)
    );
    texture_path$setup$s3_q s3_q(
        .d(s3_q$d),
        .q(s3_q$q),
        .clock(s3_q$clock)
    );
    
    // Update code
    always @(*) begin
        step$clock = clock;
        busy$clock = clock;
        done_r$clock = clock;
        neg$clock = clock;
        e1x$clock = clock;
        e1y$clock = clock;
        e2x$clock = clock;
        e2y$clock = clock;
        mant$clock = clock;
        exp$clock = clock;
        prod$clock = clock;
        acc$clock = clock;
        ox$clock = clock;
        oy$clock = clock;
        a0_sq$clock = clock;
        a0_tq$clock = clock;
        a0_q$clock = clock;
        s1_valid$clock = clock;
        s1_x$clock = clock;
        s1_y$clock = clock;
        s2_valid$clock = clock;
        s3_valid$clock = clock;
        s3_sq$clock = clock;
        s3_tq$clock = clock;
        s3_q$clock = clock;
        step$d = step$q;
        busy$d = busy$q;
        done_r$d = done_r$q;
        neg$d = neg$q;
        e1x$d = e1x$q;
        e1y$d = e1y$q;
        e2x$d = e2x$q;
        e2y$d = e2y$q;
        mant$d = mant$q;
        exp$d = exp$q;
        prod$d = prod$q;
        acc$d = acc$q;
        ox$d = ox$q;
        oy$d = oy$q;
        a0_sq$d = a0_sq$q;
        a0_tq$d = a0_tq$q;
        a0_q$d = a0_q$q;
        s1_valid$d = s1_valid$q;
        s1_x$d = s1_x$q;
        s1_y$d = s1_y$q;
        s2_valid$d = s2_valid$q;
        s3_valid$d = s3_valid$q;
        s3_sq$d = s3_sq$q;
        s3_tq$d = s3_tq$q;
        s3_q$d = s3_q$q;
        g_sq$0$clock = clock;
        g_tq$0$clock = clock;
        g_q$0$clock = clock;
        lod_sq$0$clock = clock;
        lod_tq$0$clock = clock;
        lod_q$0$clock = clock;
        s2_sq$0$clock = clock;
        s2_tq$0$clock = clock;
        s2_q$0$clock = clock;
        g_sq$0$d = g_sq$0$q;
        g_tq$0$d = g_tq$0$q;
        g_q$0$d = g_q$0$q;
        lod_sq$0$d = lod_sq$0$q;
        lod_tq$0$d = lod_tq$0$q;
        lod_q$0$d = lod_q$0$q;
        g_sq$1$clock = clock;
        g_tq$1$clock = clock;
        g_q$1$clock = clock;
        lod_sq$1$clock = clock;
        lod_tq$1$clock = clock;
        lod_q$1$clock = clock;
        s2_sq$1$clock = clock;
        s2_tq$1$clock = clock;
        s2_q$1$clock = clock;
        g_sq$1$d = g_sq$1$q;
        g_tq$1$d = g_tq$1$q;
        g_q$1$d = g_q$1$q;
        lod_sq$1$d = lod_sq$1$q;
        lod_tq$1$d = lod_tq$1$q;
        lod_q$1$d = lod_q$1$q;
        d1$0$clock = clock;
        d2$0$clock = clock;
        d1$0$d = d1$0$q;
        d2$0$d = d2$0$q;
        d1$1$clock = clock;
        d2$1$clock = clock;
        d1$1$d = d1$1$q;
        d2$1$d = d2$1$q;
        d1$2$clock = clock;
        d2$2$clock = clock;
        d1$2$d = d1$2$q;
        d2$2$d = d2$2$q;
        sx_pos$0$x = tri$x0;
        sx_pos$1$x = tri$y0;
        sx_pos$2$x = tri$x1;
        sx_pos$3$x = tri$y1;
        sx_pos$4$x = tri$x2;
        sx_pos$5$x = tri$y2;
        sx_st$0$x = tri$sq0;
        sx_st$1$x = tri$sq1;
        sx_st$2$x = tri$sq2;
        sx_st$3$x = tri$tq0;
        sx_st$4$x = tri$tq1;
        sx_st$5$x = tri$tq2;
        sx_e1x$x = e1x$q;
        sx_e2x$x = e2x$q;
        sel_d = 32'h0;
        mul_b = 32'h0;
        if (step$q == 32'h4) begin
            sel_d = d1$0$q;
            mul_b = e2y$q;
        end
        if (step$q == 32'h5) begin
            sel_d = d2$0$q;
            mul_b = e1y$q;
        end
        if (step$q == 32'h8) begin
            sel_d = d2$0$q;
            mul_b = e1x$q;
        end
        if (step$q == 32'h9) begin
            sel_d = d1$0$q;
            mul_b = e2x$q;
        end
        if (step$q == 32'hc) begin
            sel_d = d1$1$q;
            mul_b = e2y$q;
        end
        if (step$q == 32'hd) begin
            sel_d = d2$1$q;
            mul_b = e1y$q;
        end
        if (step$q == 32'h10) begin
            sel_d = d2$1$q;
            mul_b = e1x$q;
        end
        if (step$q == 32'h11) begin
            sel_d = d1$1$q;
            mul_b = e2x$q;
        end
        if (step$q == 32'h14) begin
            sel_d = d1$2$q;
            mul_b = e2y$q;
        end
        if (step$q == 32'h15) begin
            sel_d = d2$2$q;
            mul_b = e1y$q;
        end
        if (step$q == 32'h18) begin
            sel_d = d2$2$q;
            mul_b = e1x$q;
        end
        if (step$q == 32'h19) begin
            sel_d = d1$2$q;
            mul_b = e2x$q;
        end
        sx_d$x = sel_d;
        mul_a = sx_d$y;
        if (step$q == 32'h0) begin
            mul_a = sx_e1x$y;
            mul_b = e2y$q;
        end
        if (step$q == 32'h1) begin
            mul_a = sx_e2x$y;
            mul_b = e1y$q;
        end
        if (step$q[(32'h0)+:(2)] == 32'h3) begin
            mul_a = ((acc$q) & 48'hffffffffffff);
            mul_b = ((mant$q) & 26'h3ffffff);
        end
        mul$a = mul_a;
        mul$b = mul_b;
        prod$d = mul$p;
        k1 = ((exp$q) & 7'h7f) + pre;
        zs = prod$q >> k1;
        if (prod$q[mp_msb]) begin
            zs = ~((~prod$q) >> k1);
        end
        y1 = zs + 32'h1;
        exact = (y1 >> 32'h1) | (y1 & mp_top);
        t_st = exact + half_st;
        u_st = t_st + bias_st;
        ts_st = t_st >> sh_st;
        l_st = ((ts_st) & 33'h1ffffffff);
        if (u_st >= lim_st) begin
            l_st = max_st;
            if (t_st[mp_msb]) begin
                l_st = min_st;
            end
        end
        t_q = exact + half_q;
        u_q = t_q + bias_q;
        ts_q = t_q >> sh_q;
        l_q = ((ts_q) & 30'h3fffffff);
        if (u_q >= lim_q) begin
            l_q = max_q;
            if (t_q[mp_msb]) begin
                l_q = min_q;
            end
        end
        if (busy$q) begin
            step$d = step$q + 32'h1;
            if (step$q[(32'h0)+:(2)] == 32'h1) begin
                acc$d = prod$q;
            end
            if (step$q[(32'h0)+:(2)] == 32'h2) begin
                acc$d = acc$q - prod$q;
                if (neg$q) begin
                    acc$d = prod$q - acc$q;
                end
            end
            if (step$q == 32'h3) begin
                neg$d = acc$q[mp_msb];
            end
            if (step$q == 32'h8) begin
                g_sq$0$d = ((exact) & 47'h7fffffffffff);
                lod_sq$0$d = l_st;
            end
            if (step$q == 32'hc) begin
                g_sq$1$d = ((exact) & 47'h7fffffffffff);
                lod_sq$1$d = l_st;
            end
            if (step$q == 32'h10) begin
                g_tq$0$d = ((exact) & 47'h7fffffffffff);
                lod_tq$0$d = l_st;
            end
            if (step$q == 32'h14) begin
                g_tq$1$d = ((exact) & 47'h7fffffffffff);
                lod_tq$1$d = l_st;
            end
            if (step$q == 32'h18) begin
                g_q$0$d = ((exact) & 40'hffffffffff);
                lod_q$0$d = l_q;
            end
            if (step$q == 32'h1c) begin
                g_q$1$d = ((exact) & 40'hffffffffff);
                lod_q$1$d = l_q;
            end
            if (step$q == 32'h1c) begin
                busy$d = 1'b0;
                done_r$d = 1'b1;
            end
        end
        if (start) begin
            busy$d = 1'b1;
            done_r$d = 1'b0;
            step$d = 32'h0;
            neg$d = 1'b0;
            e1x$d = sx_pos$2$y - sx_pos$0$y;
            e1y$d = sx_pos$3$y - sx_pos$1$y;
            e2x$d = sx_pos$4$y - sx_pos$0$y;
            e2y$d = sx_pos$5$y - sx_pos$1$y;
            d1$0$d = sx_st$1$y - sx_st$0$y;
            d2$0$d = sx_st$2$y - sx_st$0$y;
            d1$1$d = sx_st$4$y - sx_st$3$y;
            d2$1$d = sx_st$5$y - sx_st$3$y;
            d1$2$d = ((tri$q1) & 30'h3fffffff) - ((tri$q0) & 30'h3fffffff);
            d2$2$d = ((tri$q2) & 30'h3fffffff) - ((tri$q0) & 30'h3fffffff);
            mant$d = tri$mant;
            exp$d = tri$exp;
            ox$d = ((sx_pos$0$y) & 18'h3ffff);
            oy$d = ((sx_pos$1$y) & 18'h3ffff);
            a0_sq$d = ((sx_st$0$y) & 47'h7fffffffffff) << rs;
            a0_tq$d = ((sx_st$3$y) & 47'h7fffffffffff) << rs;
            a0_q$d = ((tri$q0) & 40'hffffffffff) << rs;
        end
        done = done_r$q;
        dsq_x = lod_sq$0$q;
        dsq_y = lod_sq$1$q;
        dtq_x = lod_tq$0$q;
        dtq_y = lod_tq$1$q;
        dq_x = lod_q$0$q;
        dq_y = lod_q$1$q;
        mul_sq$0$a = g_sq$0$q;
        mul_tq$0$a = g_tq$0$q;
        mul_q$0$a = g_q$0$q;
        mul_sq$1$a = g_sq$1$q;
        mul_tq$1$a = g_tq$1$q;
        mul_q$1$a = g_q$1$q;
        mul_sq$0$b = s1_x$q;
        mul_tq$0$b = s1_x$q;
        mul_q$0$b = s1_x$q;
        mul_sq$1$b = s1_y$q;
        mul_tq$1$b = s1_y$q;
        mul_q$1$b = s1_y$q;
        sum_sq = a0_sq$q + s2_sq$0$q + s2_sq$1$q + half_f;
        sum_tq = a0_tq$q + s2_tq$0$q + s2_tq$1$q + half_f;
        sum_q = a0_q$q + s2_q$0$q + s2_q$1$q + ((half_f) & 40'hffffffffff);
        w_sq = ((sum_sq >> rs) & 30'h3fffffff);
        w_tq = ((sum_tq >> rs) & 30'h3fffffff);
        w_q = ((sum_q >> rs) & 23'h7fffff);
        s2_sq$0$d = s2_sq$0$q;
        s2_tq$0$d = s2_tq$0$q;
        s2_q$0$d = s2_q$0$q;
        s2_sq$1$d = s2_sq$1$q;
        s2_tq$1$d = s2_tq$1$q;
        s2_q$1$d = s2_q$1$q;
        if (en) begin
            s1_valid$d = inp_valid;
            s1_x$d = (((inp_x) & 18'h3ffff) << sub) + centre - ox$q;
            s1_y$d = (((inp_y) & 18'h3ffff) << sub) + centre - oy$q;
            s2_valid$d = s1_valid$q;
            s2_sq$0$d = mul_sq$0$p;
            s2_tq$0$d = mul_tq$0$p;
            s2_q$0$d = mul_q$0$p;
            s2_sq$1$d = mul_sq$1$p;
            s2_tq$1$d = mul_tq$1$p;
            s2_q$1$d = mul_q$1$p;
            s3_valid$d = s2_valid$q;
            s3_sq$d = ((w_sq) & 29'h1fffffff);
            if (~w_sq[ws_msb] & w_sq[ws_top]) begin
                s3_sq$d = st_max;
            end
            if (w_sq[ws_msb] & ~w_sq[ws_top]) begin
                s3_sq$d = st_min;
            end
            s3_tq$d = ((w_tq) & 29'h1fffffff);
            if (~w_tq[ws_msb] & w_tq[ws_top]) begin
                s3_tq$d = st_max;
            end
            if (w_tq[ws_msb] & ~w_tq[ws_top]) begin
                s3_tq$d = st_min;
            end
            s3_q$d = ((w_q) & 21'h1fffff);
            if (w_q[wq_top]) begin
                s3_q$d = q_max;
            end
            if (w_q[wq_msb]) begin
                s3_q$d = 32'h0;
            end
        end
        out_valid = s3_valid$q;
        out_sq = s3_sq$q;
        out_tq = s3_tq$q;
        out_q = s3_q$q;
    end
    
endmodule // texture_path$setup


module texture_path$setup$a0_q(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$setup$a0_q


module texture_path$setup$a0_sq(d,q,clock);
    
    // Module arguments
    input wire  [46:0] d;
    output reg  [46:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 47'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$setup$a0_sq


module texture_path$setup$a0_tq(d,q,clock);
    
    // Module arguments
    input wire  [46:0] d;
    output reg  [46:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 47'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$setup$a0_tq


module texture_path$setup$acc(d,q,clock);
    
    // Module arguments
    input wire  [73:0] d;
    output reg  [73:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 74'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$setup$acc


module texture_path$setup$busy(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$setup$busy


module texture_path$setup$d1$0(d,q,clock);
    
    // Module arguments
    input wire  [29:0] d;
    output reg  [29:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 30'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$setup$d1$0


module texture_path$setup$d1$1(d,q,clock);
    
    // Module arguments
    input wire  [29:0] d;
    output reg  [29:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 30'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$setup$d1$1


module texture_path$setup$d1$2(d,q,clock);
    
    // Module arguments
    input wire  [29:0] d;
    output reg  [29:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 30'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$setup$d1$2


module texture_path$setup$d2$0(d,q,clock);
    
    // Module arguments
    input wire  [29:0] d;
    output reg  [29:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 30'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$setup$d2$0


module texture_path$setup$d2$1(d,q,clock);
    
    // Module arguments
    input wire  [29:0] d;
    output reg  [29:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 30'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$setup$d2$1


module texture_path$setup$d2$2(d,q,clock);
    
    // Module arguments
    input wire  [29:0] d;
    output reg  [29:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 30'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$setup$d2$2


module texture_path$setup$done_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$setup$done_r


module texture_path$setup$e1x(d,q,clock);
    
    // Module arguments
    input wire  [25:0] d;
    output reg  [25:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 26'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$setup$e1x


module texture_path$setup$e1y(d,q,clock);
    
    // Module arguments
    input wire  [25:0] d;
    output reg  [25:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 26'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$setup$e1y


module texture_path$setup$e2x(d,q,clock);
    
    // Module arguments
    input wire  [25:0] d;
    output reg  [25:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 26'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$setup$e2x


module texture_path$setup$e2y(d,q,clock);
    
    // Module arguments
    input wire  [25:0] d;
    output reg  [25:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 26'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$setup$e2y


module texture_path$setup$exp(d,q,clock);
    
    // Module arguments
    input wire  [5:0] d;
    output reg  [5:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 6'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$setup$exp


module texture_path$setup$g_q$0(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$setup$g_q$0


module texture_path$setup$g_q$1(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$setup$g_q$1


module texture_path$setup$g_sq$0(d,q,clock);
    
    // Module arguments
    input wire  [46:0] d;
    output reg  [46:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 47'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$setup$g_sq$0


module texture_path$setup$g_sq$1(d,q,clock);
    
    // Module arguments
    input wire  [46:0] d;
    output reg  [46:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 47'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$setup$g_sq$1


module texture_path$setup$g_tq$0(d,q,clock);
    
    // Module arguments
    input wire  [46:0] d;
    output reg  [46:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 47'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$setup$g_tq$0


module texture_path$setup$g_tq$1(d,q,clock);
    
    // Module arguments
    input wire  [46:0] d;
    output reg  [46:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 47'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$setup$g_tq$1


module texture_path$setup$lod_q$0(d,q,clock);
    
    // Module arguments
    input wire  [29:0] d;
    output reg  [29:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 30'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$setup$lod_q$0


module texture_path$setup$lod_q$1(d,q,clock);
    
    // Module arguments
    input wire  [29:0] d;
    output reg  [29:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 30'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$setup$lod_q$1


module texture_path$setup$lod_sq$0(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$setup$lod_sq$0


module texture_path$setup$lod_sq$1(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$setup$lod_sq$1


module texture_path$setup$lod_tq$0(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$setup$lod_tq$0


module texture_path$setup$lod_tq$1(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$setup$lod_tq$1


module texture_path$setup$mant(d,q,clock);
    
    // Module arguments
    input wire  [24:0] d;
    output reg  [24:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 25'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$setup$mant


module texture_path$setup$mul(a,b,p);
    
    // Module arguments
    input wire  [47:0] a;
    input wire  [25:0] b;
    output reg  [73:0] p;
    
    // Update code (custom)
    // p = low 74 bits of a * b, both signed: a signed 74-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_path$setup$mul


module texture_path$setup$mul_q$0(a,b,p);
    
    // Module arguments
    input wire  [39:0] a;
    input wire  [17:0] b;
    output reg  [39:0] p;
    
    // Update code (custom)
    // p = low 40 bits of a * b, both signed: a signed 40-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_path$setup$mul_q$0


module texture_path$setup$mul_q$1(a,b,p);
    
    // Module arguments
    input wire  [39:0] a;
    input wire  [17:0] b;
    output reg  [39:0] p;
    
    // Update code (custom)
    // p = low 40 bits of a * b, both signed: a signed 40-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_path$setup$mul_q$1


module texture_path$setup$mul_sq$0(a,b,p);
    
    // Module arguments
    input wire  [46:0] a;
    input wire  [17:0] b;
    output reg  [46:0] p;
    
    // Update code (custom)
    // p = low 47 bits of a * b, both signed: a signed 47-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_path$setup$mul_sq$0


module texture_path$setup$mul_sq$1(a,b,p);
    
    // Module arguments
    input wire  [46:0] a;
    input wire  [17:0] b;
    output reg  [46:0] p;
    
    // Update code (custom)
    // p = low 47 bits of a * b, both signed: a signed 47-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_path$setup$mul_sq$1


module texture_path$setup$mul_tq$0(a,b,p);
    
    // Module arguments
    input wire  [46:0] a;
    input wire  [17:0] b;
    output reg  [46:0] p;
    
    // Update code (custom)
    // p = low 47 bits of a * b, both signed: a signed 47-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_path$setup$mul_tq$0


module texture_path$setup$mul_tq$1(a,b,p);
    
    // Module arguments
    input wire  [46:0] a;
    input wire  [17:0] b;
    output reg  [46:0] p;
    
    // Update code (custom)
    // p = low 47 bits of a * b, both signed: a signed 47-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_path$setup$mul_tq$1


module texture_path$setup$neg(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$setup$neg


module texture_path$setup$ox(d,q,clock);
    
    // Module arguments
    input wire  [17:0] d;
    output reg  [17:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 18'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$setup$ox


module texture_path$setup$oy(d,q,clock);
    
    // Module arguments
    input wire  [17:0] d;
    output reg  [17:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 18'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$setup$oy


module texture_path$setup$prod(d,q,clock);
    
    // Module arguments
    input wire  [73:0] d;
    output reg  [73:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 74'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$setup$prod


module texture_path$setup$s1_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$setup$s1_valid


module texture_path$setup$s1_x(d,q,clock);
    
    // Module arguments
    input wire  [17:0] d;
    output reg  [17:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 18'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$setup$s1_x


module texture_path$setup$s1_y(d,q,clock);
    
    // Module arguments
    input wire  [17:0] d;
    output reg  [17:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 18'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$setup$s1_y


module texture_path$setup$s2_q$0(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$setup$s2_q$0


module texture_path$setup$s2_q$1(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$setup$s2_q$1


module texture_path$setup$s2_sq$0(d,q,clock);
    
    // Module arguments
    input wire  [46:0] d;
    output reg  [46:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 47'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$setup$s2_sq$0


module texture_path$setup$s2_sq$1(d,q,clock);
    
    // Module arguments
    input wire  [46:0] d;
    output reg  [46:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 47'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$setup$s2_sq$1


module texture_path$setup$s2_tq$0(d,q,clock);
    
    // Module arguments
    input wire  [46:0] d;
    output reg  [46:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 47'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$setup$s2_tq$0


module texture_path$setup$s2_tq$1(d,q,clock);
    
    // Module arguments
    input wire  [46:0] d;
    output reg  [46:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 47'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$setup$s2_tq$1


module texture_path$setup$s2_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$setup$s2_valid


module texture_path$setup$s3_q(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$setup$s3_q


module texture_path$setup$s3_sq(d,q,clock);
    
    // Module arguments
    input wire  [28:0] d;
    output reg  [28:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 29'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$setup$s3_sq


module texture_path$setup$s3_tq(d,q,clock);
    
    // Module arguments
    input wire  [28:0] d;
    output reg  [28:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 29'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$setup$s3_tq


module texture_path$setup$s3_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$setup$s3_valid


module texture_path$setup$step(d,q,clock);
    
    // Module arguments
    input wire  [4:0] d;
    output reg  [4:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 5'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$setup$step


module texture_path$setup$sx_d(x,y);
    
    // Module arguments
    input wire  [29:0] x;
    output reg  [47:0] y;
    
    // Constant declarations
    localparam  msb = 8'h1d;
    localparam  ext = 48'hffffc0000000;
    
    // Update code
    always @(*) begin
        y = ((x) & 48'hffffffffffff);
        if (x[msb]) begin
            y = ((x) & 48'hffffffffffff) | ext;
        end
    end
    
endmodule // texture_path$setup$sx_d


module texture_path$setup$sx_e1x(x,y);
    
    // Module arguments
    input wire  [25:0] x;
    output reg  [47:0] y;
    
    // Constant declarations
    localparam  msb = 8'h19;
    localparam  ext = 48'hfffffc000000;
    
    // Update code
    always @(*) begin
        y = ((x) & 48'hffffffffffff);
        if (x[msb]) begin
            y = ((x) & 48'hffffffffffff) | ext;
        end
    end
    
endmodule // texture_path$setup$sx_e1x


module texture_path$setup$sx_e2x(x,y);
    
    // Module arguments
    input wire  [25:0] x;
    output reg  [47:0] y;
    
    // Constant declarations
    localparam  msb = 8'h19;
    localparam  ext = 48'hfffffc000000;
    
    // Update code
    always @(*) begin
        y = ((x) & 48'hffffffffffff);
        if (x[msb]) begin
            y = ((x) & 48'hffffffffffff) | ext;
        end
    end
    
endmodule // texture_path$setup$sx_e2x


module texture_path$setup$sx_pos$0(x,y);
    
    // Module arguments
    input wire  [15:0] x;
    output reg  [25:0] y;
    
    // Constant declarations
    localparam  msb = 8'hf;
    localparam  ext = 26'h3ff0000;
    
    // Update code
    always @(*) begin
        y = ((x) & 26'h3ffffff);
        if (x[msb]) begin
            y = ((x) & 26'h3ffffff) | ext;
        end
    end
    
endmodule // texture_path$setup$sx_pos$0


module texture_path$setup$sx_pos$1(x,y);
    
    // Module arguments
    input wire  [15:0] x;
    output reg  [25:0] y;
    
    // Constant declarations
    localparam  msb = 8'hf;
    localparam  ext = 26'h3ff0000;
    
    // Update code
    always @(*) begin
        y = ((x) & 26'h3ffffff);
        if (x[msb]) begin
            y = ((x) & 26'h3ffffff) | ext;
        end
    end
    
endmodule // texture_path$setup$sx_pos$1


module texture_path$setup$sx_pos$2(x,y);
    
    // Module arguments
    input wire  [15:0] x;
    output reg  [25:0] y;
    
    // Constant declarations
    localparam  msb = 8'hf;
    localparam  ext = 26'h3ff0000;
    
    // Update code
    always @(*) begin
        y = ((x) & 26'h3ffffff);
        if (x[msb]) begin
            y = ((x) & 26'h3ffffff) | ext;
        end
    end
    
endmodule // texture_path$setup$sx_pos$2


module texture_path$setup$sx_pos$3(x,y);
    
    // Module arguments
    input wire  [15:0] x;
    output reg  [25:0] y;
    
    // Constant declarations
    localparam  msb = 8'hf;
    localparam  ext = 26'h3ff0000;
    
    // Update code
    always @(*) begin
        y = ((x) & 26'h3ffffff);
        if (x[msb]) begin
            y = ((x) & 26'h3ffffff) | ext;
        end
    end
    
endmodule // texture_path$setup$sx_pos$3


module texture_path$setup$sx_pos$4(x,y);
    
    // Module arguments
    input wire  [15:0] x;
    output reg  [25:0] y;
    
    // Constant declarations
    localparam  msb = 8'hf;
    localparam  ext = 26'h3ff0000;
    
    // Update code
    always @(*) begin
        y = ((x) & 26'h3ffffff);
        if (x[msb]) begin
            y = ((x) & 26'h3ffffff) | ext;
        end
    end
    
endmodule // texture_path$setup$sx_pos$4


module texture_path$setup$sx_pos$5(x,y);
    
    // Module arguments
    input wire  [15:0] x;
    output reg  [25:0] y;
    
    // Constant declarations
    localparam  msb = 8'hf;
    localparam  ext = 26'h3ff0000;
    
    // Update code
    always @(*) begin
        y = ((x) & 26'h3ffffff);
        if (x[msb]) begin
            y = ((x) & 26'h3ffffff) | ext;
        end
    end
    
endmodule // texture_path$setup$sx_pos$5


module texture_path$setup$sx_st$0(x,y);
    
    // Module arguments
    input wire  [28:0] x;
    output reg  [29:0] y;
    
    // Constant declarations
    localparam  msb = 8'h1c;
    localparam  ext = 30'h20000000;
    
    // Update code
    always @(*) begin
        y = ((x) & 30'h3fffffff);
        if (x[msb]) begin
            y = ((x) & 30'h3fffffff) | ext;
        end
    end
    
endmodule // texture_path$setup$sx_st$0


module texture_path$setup$sx_st$1(x,y);
    
    // Module arguments
    input wire  [28:0] x;
    output reg  [29:0] y;
    
    // Constant declarations
    localparam  msb = 8'h1c;
    localparam  ext = 30'h20000000;
    
    // Update code
    always @(*) begin
        y = ((x) & 30'h3fffffff);
        if (x[msb]) begin
            y = ((x) & 30'h3fffffff) | ext;
        end
    end
    
endmodule // texture_path$setup$sx_st$1


module texture_path$setup$sx_st$2(x,y);
    
    // Module arguments
    input wire  [28:0] x;
    output reg  [29:0] y;
    
    // Constant declarations
    localparam  msb = 8'h1c;
    localparam  ext = 30'h20000000;
    
    // Update code
    always @(*) begin
        y = ((x) & 30'h3fffffff);
        if (x[msb]) begin
            y = ((x) & 30'h3fffffff) | ext;
        end
    end
    
endmodule // texture_path$setup$sx_st$2


module texture_path$setup$sx_st$3(x,y);
    
    // Module arguments
    input wire  [28:0] x;
    output reg  [29:0] y;
    
    // Constant declarations
    localparam  msb = 8'h1c;
    localparam  ext = 30'h20000000;
    
    // Update code
    always @(*) begin
        y = ((x) & 30'h3fffffff);
        if (x[msb]) begin
            y = ((x) & 30'h3fffffff) | ext;
        end
    end
    
endmodule // texture_path$setup$sx_st$3


module texture_path$setup$sx_st$4(x,y);
    
    // Module arguments
    input wire  [28:0] x;
    output reg  [29:0] y;
    
    // Constant declarations
    localparam  msb = 8'h1c;
    localparam  ext = 30'h20000000;
    
    // Update code
    always @(*) begin
        y = ((x) & 30'h3fffffff);
        if (x[msb]) begin
            y = ((x) & 30'h3fffffff) | ext;
        end
    end
    
endmodule // texture_path$setup$sx_st$4


module texture_path$setup$sx_st$5(x,y);
    
    // Module arguments
    input wire  [28:0] x;
    output reg  [29:0] y;
    
    // Constant declarations
    localparam  msb = 8'h1c;
    localparam  ext = 30'h20000000;
    
    // Update code
    always @(*) begin
        y = ((x) & 30'h3fffffff);
        if (x[msb]) begin
            y = ((x) & 30'h3fffffff) | ext;
        end
    end
    
endmodule // texture_path$setup$sx_st$5


module texture_path$side(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [5:0] read_address;
    input wire  read_clock;
    output reg  [38:0] read_data;
    input wire  [5:0] write_address;
    input wire  write_clock;
    input wire  [38:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[38:0] mem[63:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // texture_path$side


module texture_path$unit(clock,inp_valid,inp_ready,inp_sq,inp_tq,inp_q,inp_dsq_x,inp_dsq_y,inp_dtq_x,inp_dtq_y,inp_dq_x,inp_dq_y,inp_cf,inp_tag,st_load,st$ws,st$hs,st$levels,st$base,st$min_linear,st$mag_linear,st$mip,st$wrap_s,st$wrap_t,st$format,st$gaussian,st$env,inp_flush,out_valid,out_ready,out_rgba,out_tag,mem$valid,mem$addr,mem$ack,mem$rvalid,mem$rdata,counters$hits,counters$misses,counters$fills,idle);
    
    // Module arguments
    input wire  clock;
    input wire  inp_valid;
    output reg  inp_ready;
    input wire  [28:0] inp_sq;
    input wire  [28:0] inp_tq;
    input wire  [20:0] inp_q;
    input wire  [32:0] inp_dsq_x;
    input wire  [32:0] inp_dsq_y;
    input wire  [32:0] inp_dtq_x;
    input wire  [32:0] inp_dtq_y;
    input wire  [29:0] inp_dq_x;
    input wire  [29:0] inp_dq_y;
    input wire  [23:0] inp_cf;
    input wire  [31:0] inp_tag;
    input wire  st_load;
    input wire  [3:0] st$ws;
    input wire  [3:0] st$hs;
    input wire  [3:0] st$levels;
    input wire  [25:0] st$base;
    input wire  st$min_linear;
    input wire  st$mag_linear;
    input wire  [1:0] st$mip;
    input wire  [1:0] st$wrap_s;
    input wire  [1:0] st$wrap_t;
    input wire  [2:0] st$format;
    input wire  st$gaussian;
    input wire  [2:0] st$env;
    input wire  inp_flush;
    output reg  out_valid;
    input wire  out_ready;
    output reg  [31:0] out_rgba;
    output reg  [31:0] out_tag;
    output wire  mem$valid;
    output wire  [25:0] mem$addr;
    input wire  mem$ack;
    input wire  mem$rvalid;
    input wire  [31:0] mem$rdata;
    output wire  [31:0] counters$hits;
    output wire  [31:0] counters$misses;
    output wire  [31:0] counters$fills;
    output reg  idle;
    
    // Stub signals
    reg  coords$clock;
    reg  coords$en;
    reg  coords$inp_valid;
    reg  [28:0] coords$inp_sq;
    reg  [28:0] coords$inp_tq;
    reg  [20:0] coords$inp_q;
    reg  [32:0] coords$inp_dsq_x;
    reg  [32:0] coords$inp_dsq_y;
    reg  [32:0] coords$inp_dtq_x;
    reg  [32:0] coords$inp_dtq_y;
    reg  [29:0] coords$inp_dq_x;
    reg  [29:0] coords$inp_dq_y;
    reg  [3:0] coords$inp_ws;
    reg  [3:0] coords$inp_hs;
    wire  coords$out_valid;
    wire  [28:0] coords$out_s;
    wire  [28:0] coords$out_t;
    wire  [31:0] coords$out_lambda;
    reg  address$clock;
    reg  address$en;
    reg  address$inp_valid;
    reg  [28:0] address$s;
    reg  [28:0] address$t;
    reg  [31:0] address$lambda;
    reg  address$second;
    reg  [3:0] address$ws;
    reg  [3:0] address$hs;
    reg  [3:0] address$levels;
    reg  [25:0] address$base;
    reg  address$min_linear;
    reg  address$mag_linear;
    reg  [1:0] address$mip;
    reg  [1:0] address$wrap_s;
    reg  [1:0] address$wrap_t;
    wire  address$inp_two_levels;
    wire  address$out_valid;
    wire  address$out_second;
    wire  [3:0] address$lanes;
    wire  [25:0] address$addr0;
    wire  [25:0] address$addr1;
    wire  [25:0] address$addr2;
    wire  [25:0] address$addr3;
    wire  [7:0] address$banks;
    wire  [7:0] address$alpha;
    wire  [7:0] address$beta;
    wire  address$two_levels;
    wire  [5:0] address$frac;
    reg  cache$clock;
    reg  cache$inp_valid;
    wire  cache$inp_ready;
    reg  [3:0] cache$inp_en;
    reg  [25:0] cache$inp_addr0;
    reg  [25:0] cache$inp_addr1;
    reg  [25:0] cache$inp_addr2;
    reg  [25:0] cache$inp_addr3;
    reg  [63:0] cache$inp_side;
    reg  cache$inp_flush;
    wire  cache$out_valid;
    reg  cache$out_ready;
    wire  [31:0] cache$out_data0;
    wire  [31:0] cache$out_data1;
    wire  [31:0] cache$out_data2;
    wire  [31:0] cache$out_data3;
    wire  [63:0] cache$out_side;
    reg  [31:0] pick$0$data0;
    reg  [31:0] pick$0$data1;
    reg  [31:0] pick$0$data2;
    reg  [31:0] pick$0$data3;
    reg  [1:0] pick$0$bank;
    wire  [31:0] pick$0$word;
    reg  [31:0] pick$1$data0;
    reg  [31:0] pick$1$data1;
    reg  [31:0] pick$1$data2;
    reg  [31:0] pick$1$data3;
    reg  [1:0] pick$1$bank;
    wire  [31:0] pick$1$word;
    reg  [31:0] pick$2$data0;
    reg  [31:0] pick$2$data1;
    reg  [31:0] pick$2$data2;
    reg  [31:0] pick$2$data3;
    reg  [1:0] pick$2$bank;
    wire  [31:0] pick$2$word;
    reg  [31:0] pick$3$data0;
    reg  [31:0] pick$3$data1;
    reg  [31:0] pick$3$data2;
    reg  [31:0] pick$3$data3;
    reg  [1:0] pick$3$bank;
    wire  [31:0] pick$3$word;
    reg  filter$clock;
    reg  filter$en;
    reg  filter$inp_valid;
    reg  [31:0] filter$inp_words0_0;
    reg  [31:0] filter$inp_words0_1;
    reg  [31:0] filter$inp_words0_2;
    reg  [31:0] filter$inp_words0_3;
    reg  [31:0] filter$inp_words1_0;
    reg  [31:0] filter$inp_words1_1;
    reg  [31:0] filter$inp_words1_2;
    reg  [31:0] filter$inp_words1_3;
    reg  [7:0] filter$inp_alpha0;
    reg  [7:0] filter$inp_beta0;
    reg  [7:0] filter$inp_alpha1;
    reg  [7:0] filter$inp_beta1;
    reg  [5:0] filter$inp_frac;
    reg  filter$inp_two_levels;
    reg  [2:0] filter$inp_format;
    reg  filter$inp_gaussian;
    reg  [2:0] filter$inp_env;
    reg  [23:0] filter$inp_cf;
    wire  filter$out_valid;
    wire  [31:0] filter$out_rgba;
    reg  [5:0] cf_ram$read_address;
    reg  cf_ram$read_clock;
    wire  [23:0] cf_ram$read_data;
    reg  [5:0] cf_ram$write_address;
    reg  cf_ram$write_clock;
    reg  [23:0] cf_ram$write_data;
    reg  cf_ram$write_enable;
    reg  [5:0] tag_ram$read_address;
    reg  tag_ram$read_clock;
    wire  [31:0] tag_ram$read_data;
    reg  [5:0] tag_ram$write_address;
    reg  tag_ram$write_clock;
    reg  [31:0] tag_ram$write_data;
    reg  tag_ram$write_enable;
    reg  [3:0] r_ws$d;
    wire  [3:0] r_ws$q;
    reg  r_ws$clock;
    reg  [3:0] r_hs$d;
    wire  [3:0] r_hs$q;
    reg  r_hs$clock;
    reg  [3:0] r_levels$d;
    wire  [3:0] r_levels$q;
    reg  r_levels$clock;
    reg  [25:0] r_base$d;
    wire  [25:0] r_base$q;
    reg  r_base$clock;
    reg  r_min_linear$d;
    wire  r_min_linear$q;
    reg  r_min_linear$clock;
    reg  r_mag_linear$d;
    wire  r_mag_linear$q;
    reg  r_mag_linear$clock;
    reg  [1:0] r_mip$d;
    wire  [1:0] r_mip$q;
    reg  r_mip$clock;
    reg  [1:0] r_wrap_s$d;
    wire  [1:0] r_wrap_s$q;
    reg  r_wrap_s$clock;
    reg  [1:0] r_wrap_t$d;
    wire  [1:0] r_wrap_t$q;
    reg  r_wrap_t$clock;
    reg  [2:0] r_format$d;
    wire  [2:0] r_format$q;
    reg  r_format$clock;
    reg  r_gaussian$d;
    wire  r_gaussian$q;
    reg  r_gaussian$clock;
    reg  [2:0] r_env$d;
    wire  [2:0] r_env$q;
    reg  r_env$clock;
    reg  second$d;
    wire  second$q;
    reg  second$clock;
    reg  [5:0] wp$d;
    wire  [5:0] wp$q;
    reg  wp$clock;
    reg  [5:0] rc$d;
    wire  [5:0] rc$q;
    reg  rc$clock;
    reg  [5:0] rt$d;
    wire  [5:0] rt$q;
    reg  rt$clock;
    reg  [31:0] pair_words$0$d;
    wire  [31:0] pair_words$0$q;
    reg  pair_words$0$clock;
    reg  [31:0] pair_words$1$d;
    wire  [31:0] pair_words$1$q;
    reg  pair_words$1$clock;
    reg  [31:0] pair_words$2$d;
    wire  [31:0] pair_words$2$q;
    reg  pair_words$2$clock;
    reg  [31:0] pair_words$3$d;
    wire  [31:0] pair_words$3$q;
    reg  pair_words$3$clock;
    reg  [7:0] pair_alpha$d;
    wire  [7:0] pair_alpha$q;
    reg  pair_alpha$clock;
    reg  [7:0] pair_beta$d;
    wire  [7:0] pair_beta$q;
    reg  pair_beta$clock;
    
    // Local signals
    reg  en_f;
    reg  en_a;
    reg  en_c;
    reg  take;
    reg  accept;
    reg  [31:0] attr;
    reg  [31:0] res;
    reg  first;
    reg  whole;
    
    // Sub module instances
    texture_path$unit$coords coords(
        .clock(coords$clock),
        .en(coords$en),
        .inp_valid(coords$inp_valid),
        .inp_sq(coords$inp_sq),
        .inp_tq(coords$inp_tq),
        .inp_q(coords$inp_q),
        .inp_dsq_x(coords$inp_dsq_x),
        .inp_dsq_y(coords$inp_dsq_y),
        .inp_dtq_x(coords$inp_dtq_x),
        .inp_dtq_y(coords$inp_dtq_y),
        .inp_dq_x(coords$inp_dq_x),
        .inp_dq_y(coords$inp_dq_y),
        .inp_ws(coords$inp_ws),
        .inp_hs(coords$inp_hs),
        .out_valid(coords$out_valid),
        .out_s(coords$out_s),
        .out_t(coords$out_t),
        .out_lambda(coords$out_lambda)
    );
    texture_path$unit$address address(
        .clock(address$clock),
        .en(address$en),
        .inp_valid(address$inp_valid),
        .s(address$s),
        .t(address$t),
        .lambda(address$lambda),
        .second(address$second),
        .ws(address$ws),
        .hs(address$hs),
        .levels(address$levels),
        .base(address$base),
        .min_linear(address$min_linear),
        .mag_linear(address$mag_linear),
        .mip(address$mip),
        .wrap_s(address$wrap_s),
        .wrap_t(address$wrap_t),
        .inp_two_levels(address$inp_two_levels),
        .out_valid(address$out_valid),
        .out_second(address$out_second),
        .lanes(address$lanes),
        .addr0(address$addr0),
        .addr1(address$addr1),
        .addr2(address$addr2),
        .addr3(address$addr3),
        .banks(address$banks),
        .alpha(address$alpha),
        .beta(address$beta),
        .two_levels(address$two_levels),
        .frac(address$frac)
    );
    texture_path$unit$cache cache(
        .clock(cache$clock),
        .inp_valid(cache$inp_valid),
        .inp_ready(cache$inp_ready),
        .inp_en(cache$inp_en),
        .inp_addr0(cache$inp_addr0),
        .inp_addr1(cache$inp_addr1),
        .inp_addr2(cache$inp_addr2),
        .inp_addr3(cache$inp_addr3),
        .inp_side(cache$inp_side),
        .inp_flush(cache$inp_flush),
        .out_valid(cache$out_valid),
        .out_ready(cache$out_ready),
        .out_data0(cache$out_data0),
        .out_data1(cache$out_data1),
        .out_data2(cache$out_data2),
        .out_data3(cache$out_data3),
        .out_side(cache$out_side),
        .mem$valid(mem$valid),
        .mem$addr(mem$addr),
        .mem$ack(mem$ack),
        .mem$rvalid(mem$rvalid),
        .mem$rdata(mem$rdata),
        .counters$hits(counters$hits),
        .counters$misses(counters$misses),
        .counters$fills(counters$fills)
    );
    texture_path$unit$pick$0 pick$0(
        .data0(pick$0$data0),
        .data1(pick$0$data1),
        .data2(pick$0$data2),
        .data3(pick$0$data3),
        .bank(pick$0$bank),
        .word(pick$0$word)
    );
    texture_path$unit$pick$1 pick$1(
        .data0(pick$1$data0),
        .data1(pick$1$data1),
        .data2(pick$1$data2),
        .data3(pick$1$data3),
        .bank(pick$1$bank),
        .word(pick$1$word)
    );
    texture_path$unit$pick$2 pick$2(
        .data0(pick$2$data0),
        .data1(pick$2$data1),
        .data2(pick$2$data2),
        .data3(pick$2$data3),
        .bank(pick$2$bank),
        .word(pick$2$word)
    );
    texture_path$unit$pick$3 pick$3(
        .data0(pick$3$data0),
        .data1(pick$3$data1),
        .data2(pick$3$data2),
        .data3(pick$3$data3),
        .bank(pick$3$bank),
        .word(pick$3$word)
    );
    texture_path$unit$filter filter(
        .clock(filter$clock),
        .en(filter$en),
        .inp_valid(filter$inp_valid),
        .inp_words0_0(filter$inp_words0_0),
        .inp_words0_1(filter$inp_words0_1),
        .inp_words0_2(filter$inp_words0_2),
        .inp_words0_3(filter$inp_words0_3),
        .inp_words1_0(filter$inp_words1_0),
        .inp_words1_1(filter$inp_words1_1),
        .inp_words1_2(filter$inp_words1_2),
        .inp_words1_3(filter$inp_words1_3),
        .inp_alpha0(filter$inp_alpha0),
        .inp_beta0(filter$inp_beta0),
        .inp_alpha1(filter$inp_alpha1),
        .inp_beta1(filter$inp_beta1),
        .inp_frac(filter$inp_frac),
        .inp_two_levels(filter$inp_two_levels),
        .inp_format(filter$inp_format),
        .inp_gaussian(filter$inp_gaussian),
        .inp_env(filter$inp_env),
        .inp_cf(filter$inp_cf),
        .out_valid(filter$out_valid),
        .out_rgba(filter$out_rgba)
    );
    texture_path$unit$cf_ram cf_ram(
        .read_address(cf_ram$read_address),
        .read_clock(cf_ram$read_clock),
        .read_data(cf_ram$read_data),
        .write_address(cf_ram$write_address),
        .write_clock(cf_ram$write_clock),
        .write_data(cf_ram$write_data),
        .write_enable(cf_ram$write_enable)
    );
    texture_path$unit$tag_ram tag_ram(
        .read_address(tag_ram$read_address),
        .read_clock(tag_ram$read_clock),
        .read_data(tag_ram$read_data),
        .write_address(tag_ram$write_address),
        .write_clock(tag_ram$write_clock),
        .write_data(tag_ram$write_data),
        .write_enable(tag_ram$write_enable)
    );
    texture_path$unit$r_ws r_ws(
        .d(r_ws$d),
        .q(r_ws$q),
        .clock(r_ws$clock)
    );
    texture_path$unit$r_hs r_hs(
        .d(r_hs$d),
        .q(r_hs$q),
        .clock(r_hs$clock)
    );
    texture_path$unit$r_levels r_levels(
        .d(r_levels$d),
        .q(r_levels$q),
        .clock(r_levels$clock)
    );
    texture_path$unit$r_base r_base(
        .d(r_base$d),
        .q(r_base$q),
        .clock(r_base$clock)
    );
    texture_path$unit$r_min_linear r_min_linear(
        .d(r_min_linear$d),
        .q(r_min_linear$q),
        .clock(r_min_linear$clock)
    );
    texture_path$unit$r_mag_linear r_mag_linear(
        .d(r_mag_linear$d),
        .q(r_mag_linear$q),
        .clock(r_mag_linear$clock)
    );
    texture_path$unit$r_mip r_mip(
        .d(r_mip$d),
        .q(r_mip$q),
        .clock(r_mip$clock)
    );
    texture_path$unit$r_wrap_s r_wrap_s(
        .d(r_wrap_s$d),
        .q(r_wrap_s$q),
        .clock(r_wrap_s$clock)
    );
    texture_path$unit$r_wrap_t r_wrap_t(
        .d(r_wrap_t$d),
        .q(r_wrap_t$q),
        .clock(r_wrap_t$clock)
    );
    texture_path$unit$r_format r_format(
        .d(r_format$d),
        .q(r_format$q),
        .clock(r_format$clock)
    );
    texture_path$unit$r_gaussian r_gaussian(
        .d(r_gaussian$d),
        .q(r_gaussian$q),
        .clock(r_gaussian$clock)
    );
    texture_path$unit$r_env r_env(
        .d(r_env$d),
        .q(r_env$q),
        .clock(r_env$clock)
    );
    texture_path$unit$second second(
        .d(second$d),
        .q(second$q),
        .clock(second$clock)
    );
    texture_path$unit$wp wp(
        .d(wp$d),
        .q(wp$q),
        .clock(wp$clock)
    );
    texture_path$unit$rc rc(
        .d(rc$d),
        .q(rc$q),
        .clock(rc$clock)
    );
    texture_path$unit$rt rt(
        .d(rt$d),
        .q(rt$q),
        .clock(rt$clock)
    );
    texture_path$unit$pair_words$0 pair_words$0(
        .d(pair_words$0$d),
        .q(pair_words$0$q),
        .clock(pair_words$0$clock)
    );
    texture_path$unit$pair_words$1 pair_words$1(
        .d(pair_words$1$d),
        .q(pair_words$1$q),
        .clock(pair_words$1$clock)
    );
    texture_path$unit$pair_words$2 pair_words$2(
        .d(pair_words$2$d),
        .q(pair_words$2$q),
        .clock(pair_words$2$clock)
    );
    texture_path$unit$pair_words$3 pair_words$3(
        .d(pair_words$3$d),
        .q(pair_words$3$q),
        .clock(pair_words$3$clock)
    );
    texture_path$unit$pair_alpha pair_alpha(
        .d(pair_alpha$d),
        .q(pair_alpha$q),
        .clock(pair_alpha$clock)
    );
    texture_path$unit$pair_beta pair_beta(
        .d(pair_beta$d),
        .q(pair_beta$q),
        .clock(pair_beta$clock)
    );
    
    // Update code
    always @(*) begin
        r_ws$clock = clock;
        r_hs$clock = clock;
        r_levels$clock = clock;
        r_base$clock = clock;
        r_min_linear$clock = clock;
        r_mag_linear$clock = clock;
        r_mip$clock = clock;
        r_wrap_s$clock = clock;
        r_wrap_t$clock = clock;
        r_format$clock = clock;
        r_gaussian$clock = clock;
        r_env$clock = clock;
        second$clock = clock;
        wp$clock = clock;
        rc$clock = clock;
        rt$clock = clock;
        pair_alpha$clock = clock;
        pair_beta$clock = clock;
        r_ws$d = r_ws$q;
        r_hs$d = r_hs$q;
        r_levels$d = r_levels$q;
        r_base$d = r_base$q;
        r_min_linear$d = r_min_linear$q;
        r_mag_linear$d = r_mag_linear$q;
        r_mip$d = r_mip$q;
        r_wrap_s$d = r_wrap_s$q;
        r_wrap_t$d = r_wrap_t$q;
        r_format$d = r_format$q;
        r_gaussian$d = r_gaussian$q;
        r_env$d = r_env$q;
        second$d = second$q;
        wp$d = wp$q;
        rc$d = rc$q;
        rt$d = rt$q;
        pair_alpha$d = pair_alpha$q;
        pair_beta$d = pair_beta$q;
        pair_words$0$clock = clock;
        pair_words$0$d = pair_words$0$q;
        pair_words$1$clock = clock;
        pair_words$1$d = pair_words$1$q;
        pair_words$2$clock = clock;
        pair_words$2$d = pair_words$2$q;
        pair_words$3$clock = clock;
        pair_words$3$d = pair_words$3$q;
        if (st_load) begin
            r_ws$d = st$ws;
            r_hs$d = st$hs;
            r_levels$d = st$levels;
            r_base$d = st$base;
            r_min_linear$d = st$min_linear;
            r_mag_linear$d = st$mag_linear;
            r_mip$d = st$mip;
            r_wrap_s$d = st$wrap_s;
            r_wrap_t$d = st$wrap_t;
            r_format$d = st$format;
            r_gaussian$d = st$gaussian;
            r_env$d = st$env;
        end
        en_f = out_ready | ~filter$out_valid;
        en_a = ~address$out_valid | cache$inp_ready;
        address$clock = clock;
        address$en = en_a;
        address$inp_valid = coords$out_valid;
        address$s = coords$out_s;
        address$t = coords$out_t;
        address$lambda = coords$out_lambda;
        address$second = second$q;
        address$ws = r_ws$q;
        address$hs = r_hs$q;
        address$levels = r_levels$q;
        address$base = r_base$q;
        address$min_linear = r_min_linear$q;
        address$mag_linear = r_mag_linear$q;
        address$mip = r_mip$q;
        address$wrap_s = r_wrap_s$q;
        address$wrap_t = r_wrap_t$q;
        attr = (((address$beta) & 32'hffffffff) << 32'h18) | (((address$alpha) & 32'hffffffff) << 32'h10) | (((address$banks) & 32'hffffffff) << 32'h8) | (((address$frac) & 32'hffffffff) << 32'h2);
        if (address$two_levels) begin
            attr = (attr & ~(1 << (32'h1)) | ((1'b1) << (32'h1)));
        end
        if (address$out_second) begin
            attr = (attr & ~(1 << (32'h0)) | ((1'b1) << (32'h0)));
        end
        cache$clock = clock;
        cache$inp_valid = address$out_valid;
        cache$inp_en = address$lanes;
        cache$inp_addr0 = address$addr0;
        cache$inp_addr1 = address$addr1;
        cache$inp_addr2 = address$addr2;
        cache$inp_addr3 = address$addr3;
        cache$inp_side = ((attr) & 64'hffffffffffffffff);
        cache$inp_flush = inp_flush;
        cache$out_ready = en_f;
        take = coords$out_valid & en_a;
        en_c = ~coords$out_valid | (en_a & (~address$inp_two_levels | second$q));
        if (take) begin
            second$d = address$inp_two_levels & ~second$q;
        end
        inp_ready = en_c & ~st_load;
        accept = inp_valid & inp_ready;
        coords$clock = clock;
        coords$en = en_c;
        coords$inp_valid = inp_valid & ~st_load;
        coords$inp_sq = inp_sq;
        coords$inp_tq = inp_tq;
        coords$inp_q = inp_q;
        coords$inp_dsq_x = inp_dsq_x;
        coords$inp_dsq_y = inp_dsq_y;
        coords$inp_dtq_x = inp_dtq_x;
        coords$inp_dtq_y = inp_dtq_y;
        coords$inp_dq_x = inp_dq_x;
        coords$inp_dq_y = inp_dq_y;
        coords$inp_ws = r_ws$q;
        coords$inp_hs = r_hs$q;
        cf_ram$write_clock = clock;
        cf_ram$read_clock = clock;
        tag_ram$write_clock = clock;
        tag_ram$read_clock = clock;
        cf_ram$write_enable = accept;
        tag_ram$write_enable = accept;
        cf_ram$write_address = wp$q;
        tag_ram$write_address = wp$q;
        cf_ram$write_data = inp_cf;
        tag_ram$write_data = inp_tag;
        if (accept) begin
            wp$d = wp$q + 32'h1;
        end
        res = cache$out_side[(32'h0)+:(32)];
        pick$0$data0 = cache$out_data0;
        pick$0$data1 = cache$out_data1;
        pick$0$data2 = cache$out_data2;
        pick$0$data3 = cache$out_data3;
        pick$1$data0 = cache$out_data0;
        pick$1$data1 = cache$out_data1;
        pick$1$data2 = cache$out_data2;
        pick$1$data3 = cache$out_data3;
        pick$2$data0 = cache$out_data0;
        pick$2$data1 = cache$out_data1;
        pick$2$data2 = cache$out_data2;
        pick$2$data3 = cache$out_data3;
        pick$3$data0 = cache$out_data0;
        pick$3$data1 = cache$out_data1;
        pick$3$data2 = cache$out_data2;
        pick$3$data3 = cache$out_data3;
        pick$0$bank = res[(32'h8)+:(2)];
        pick$1$bank = res[(32'ha)+:(2)];
        pick$2$bank = res[(32'hc)+:(2)];
        pick$3$bank = res[(32'he)+:(2)];
        first = res[32'h1] & ~res[32'h0];
        whole = cache$out_valid & ~first;
        if (cache$out_valid & first & en_f) begin
            pair_words$0$d = pick$0$word;
            pair_words$1$d = pick$1$word;
            pair_words$2$d = pick$2$word;
            pair_words$3$d = pick$3$word;
            pair_alpha$d = res[(32'h10)+:(8)];
            pair_beta$d = res[(32'h18)+:(8)];
        end
        filter$clock = clock;
        filter$en = en_f;
        filter$inp_valid = whole;
        filter$inp_words0_0 = pick$0$word;
        filter$inp_words0_1 = pick$1$word;
        filter$inp_words0_2 = pick$2$word;
        filter$inp_words0_3 = pick$3$word;
        filter$inp_alpha0 = res[(32'h10)+:(8)];
        filter$inp_beta0 = res[(32'h18)+:(8)];
        if (res[32'h1]) begin
            filter$inp_words0_0 = pair_words$0$q;
            filter$inp_words0_1 = pair_words$1$q;
            filter$inp_words0_2 = pair_words$2$q;
            filter$inp_words0_3 = pair_words$3$q;
            filter$inp_alpha0 = pair_alpha$q;
            filter$inp_beta0 = pair_beta$q;
        end
        filter$inp_words1_0 = pick$0$word;
        filter$inp_words1_1 = pick$1$word;
        filter$inp_words1_2 = pick$2$word;
        filter$inp_words1_3 = pick$3$word;
        filter$inp_alpha1 = res[(32'h10)+:(8)];
        filter$inp_beta1 = res[(32'h18)+:(8)];
        filter$inp_frac = res[(32'h2)+:(6)];
        filter$inp_two_levels = res[32'h1];
        filter$inp_format = r_format$q;
        filter$inp_gaussian = r_gaussian$q;
        filter$inp_env = r_env$q;
        filter$inp_cf = cf_ram$read_data;
        cf_ram$read_address = rc$q;
        if (whole & en_f) begin
            rc$d = rc$q + 32'h1;
            cf_ram$read_address = rc$q + 32'h1;
        end
        out_valid = filter$out_valid;
        out_rgba = filter$out_rgba;
        out_tag = tag_ram$read_data;
        tag_ram$read_address = rt$q;
        if (filter$out_valid & out_ready) begin
            rt$d = rt$q + 32'h1;
            tag_ram$read_address = rt$q + 32'h1;
        end
        idle = wp$q == rt$q;
    end
    
endmodule // texture_path$unit


module texture_path$unit$address(clock,en,inp_valid,s,t,lambda,second,ws,hs,levels,base,min_linear,mag_linear,mip,wrap_s,wrap_t,inp_two_levels,out_valid,out_second,lanes,addr0,addr1,addr2,addr3,banks,alpha,beta,two_levels,frac);
    
    // Module arguments
    input wire  clock;
    input wire  en;
    input wire  inp_valid;
    input wire  [28:0] s;
    input wire  [28:0] t;
    input wire  [31:0] lambda;
    input wire  second;
    input wire  [3:0] ws;
    input wire  [3:0] hs;
    input wire  [3:0] levels;
    input wire  [25:0] base;
    input wire  min_linear;
    input wire  mag_linear;
    input wire  [1:0] mip;
    input wire  [1:0] wrap_s;
    input wire  [1:0] wrap_t;
    output reg  inp_two_levels;
    output reg  out_valid;
    output reg  out_second;
    output reg  [3:0] lanes;
    output reg  [25:0] addr0;
    output reg  [25:0] addr1;
    output reg  [25:0] addr2;
    output reg  [25:0] addr3;
    output reg  [7:0] banks;
    output reg  [7:0] alpha;
    output reg  [7:0] beta;
    output reg  two_levels;
    output reg  [5:0] frac;
    
    // Constant declarations
    localparam  bank_id$0 = 2'b0;
    localparam  bank_id$1 = 2'b1;
    localparam  bank_id$2 = 2'b10;
    localparam  bank_id$3 = 2'b11;
    localparam  lane_bit$0 = 4'h1;
    localparam  lane_bit$1 = 4'h2;
    localparam  lane_bit$2 = 4'h4;
    localparam  lane_bit$3 = 4'h8;
    localparam  pos$0 = 6'b0;
    localparam  pos$1 = 6'b1;
    localparam  pos$2 = 6'b10;
    localparam  pos$3 = 6'b11;
    localparam  pos$4 = 6'b100;
    localparam  pos$5 = 6'b101;
    localparam  pos$6 = 6'b110;
    localparam  pos$7 = 6'b111;
    localparam  pos$8 = 6'b1000;
    localparam  pos$9 = 6'b1001;
    localparam  pos$10 = 6'b1010;
    localparam  pos$11 = 6'b1011;
    localparam  pos$12 = 6'b1100;
    localparam  pos$13 = 6'b1101;
    localparam  pos$14 = 6'b1110;
    localparam  pos$15 = 6'b1111;
    localparam  pos$16 = 6'b10000;
    localparam  pos$17 = 6'b10001;
    localparam  pos$18 = 6'b10010;
    localparam  pos$19 = 6'b10011;
    localparam  pos$20 = 6'b10100;
    localparam  pos$21 = 6'b10101;
    localparam  pos$22 = 6'b10110;
    localparam  pos$23 = 6'b10111;
    localparam  pos$24 = 6'b11000;
    localparam  pos$25 = 6'b11001;
    localparam  pos_bit$0 = 26'h1;
    localparam  pos_bit$1 = 26'h2;
    localparam  pos_bit$2 = 26'h4;
    localparam  pos_bit$3 = 26'h8;
    localparam  pos_bit$4 = 26'h10;
    localparam  pos_bit$5 = 26'h20;
    localparam  pos_bit$6 = 26'h40;
    localparam  pos_bit$7 = 26'h80;
    localparam  pos_bit$8 = 26'h100;
    localparam  pos_bit$9 = 26'h200;
    localparam  pos_bit$10 = 26'h400;
    localparam  pos_bit$11 = 26'h800;
    localparam  pos_bit$12 = 26'h1000;
    localparam  pos_bit$13 = 26'h2000;
    localparam  pos_bit$14 = 26'h4000;
    localparam  pos_bit$15 = 26'h8000;
    localparam  pos_bit$16 = 26'h10000;
    localparam  pos_bit$17 = 26'h20000;
    localparam  pos_bit$18 = 26'h40000;
    localparam  pos_bit$19 = 26'h80000;
    localparam  pos_bit$20 = 26'h100000;
    localparam  pos_bit$21 = 26'h200000;
    localparam  pos_bit$22 = 26'h400000;
    localparam  pos_bit$23 = 26'h800000;
    localparam  pos_bit$24 = 26'h1000000;
    localparam  pos_bit$25 = 26'h2000000;
    
    // Stub signals
    reg  a_valid$d;
    wire  a_valid$q;
    reg  a_valid$clock;
    reg  a_second$d;
    wire  a_second$q;
    reg  a_second$clock;
    reg  [28:0] a_s$d;
    wire  [28:0] a_s$q;
    reg  a_s$clock;
    reg  [28:0] a_t$d;
    wire  [28:0] a_t$q;
    reg  a_t$clock;
    reg  a_two$d;
    wire  a_two$q;
    reg  a_two$clock;
    reg  [5:0] a_frac$d;
    wire  [5:0] a_frac$q;
    reg  a_frac$clock;
    reg  a_linear$d;
    wire  a_linear$q;
    reg  a_linear$clock;
    reg  [3:0] a_level$d;
    wire  [3:0] a_level$q;
    reg  a_level$clock;
    reg  [3:0] a_sw$d;
    wire  [3:0] a_sw$q;
    reg  a_sw$clock;
    reg  [3:0] a_sh$d;
    wire  [3:0] a_sh$q;
    reg  a_sh$clock;
    reg  [3:0] a_pw$d;
    wire  [3:0] a_pw$q;
    reg  a_pw$clock;
    reg  [3:0] a_ph$d;
    wire  [3:0] a_ph$q;
    reg  a_ph$clock;
    reg  [28:0] across$coord;
    reg  [3:0] across$size_log2;
    reg  across$linear;
    wire  [21:0] across$i0;
    wire  [21:0] across$i1;
    wire  [7:0] across$frac;
    reg  [28:0] up$coord;
    reg  [3:0] up$size_log2;
    reg  up$linear;
    wire  [21:0] up$i0;
    wire  [21:0] up$i1;
    wire  [7:0] up$frac;
    reg  b_valid$d;
    wire  b_valid$q;
    reg  b_valid$clock;
    reg  b_second$d;
    wire  b_second$q;
    reg  b_second$clock;
    reg  b_two$d;
    wire  b_two$q;
    reg  b_two$clock;
    reg  [5:0] b_frac$d;
    wire  [5:0] b_frac$q;
    reg  b_frac$clock;
    reg  [3:0] b_sw$d;
    wire  [3:0] b_sw$q;
    reg  b_sw$clock;
    reg  [3:0] b_sh$d;
    wire  [3:0] b_sh$q;
    reg  b_sh$clock;
    reg  [3:0] b_pw$d;
    wire  [3:0] b_pw$q;
    reg  b_pw$clock;
    reg  [4:0] b_pwh$d;
    wire  [4:0] b_pwh$q;
    reg  b_pwh$clock;
    reg  [21:0] b_i0$d;
    wire  [21:0] b_i0$q;
    reg  b_i0$clock;
    reg  [21:0] b_i1$d;
    wire  [21:0] b_i1$q;
    reg  b_i1$clock;
    reg  [21:0] b_j0$d;
    wire  [21:0] b_j0$q;
    reg  b_j0$clock;
    reg  [21:0] b_j1$d;
    wire  [21:0] b_j1$q;
    reg  b_j1$clock;
    reg  [7:0] b_alpha$d;
    wire  [7:0] b_alpha$q;
    reg  b_alpha$clock;
    reg  [7:0] b_beta$d;
    wire  [7:0] b_beta$q;
    reg  b_beta$clock;
    reg  [25:0] b_first$d;
    wire  [25:0] b_first$q;
    reg  b_first$clock;
    reg  [21:0] wrap$0$i;
    reg  [3:0] wrap$0$size_log2;
    reg  [1:0] wrap$0$mode;
    wire  [12:0] wrap$0$wrapped;
    reg  [21:0] wrap$1$i;
    reg  [3:0] wrap$1$size_log2;
    reg  [1:0] wrap$1$mode;
    wire  [12:0] wrap$1$wrapped;
    reg  [21:0] wrap$2$i;
    reg  [3:0] wrap$2$size_log2;
    reg  [1:0] wrap$2$mode;
    wire  [12:0] wrap$2$wrapped;
    reg  [21:0] wrap$3$i;
    reg  [3:0] wrap$3$size_log2;
    reg  [1:0] wrap$3$mode;
    wire  [12:0] wrap$3$wrapped;
    reg  [12:0] word$0$i;
    reg  [12:0] word$0$j;
    reg  [1:0] word$0$bank;
    reg  [25:0] word$0$first;
    reg  [3:0] word$0$pw;
    reg  [4:0] word$0$pwh;
    wire  [25:0] word$0$addr;
    reg  [12:0] word$1$i;
    reg  [12:0] word$1$j;
    reg  [1:0] word$1$bank;
    reg  [25:0] word$1$first;
    reg  [3:0] word$1$pw;
    reg  [4:0] word$1$pwh;
    wire  [25:0] word$1$addr;
    reg  [12:0] word$2$i;
    reg  [12:0] word$2$j;
    reg  [1:0] word$2$bank;
    reg  [25:0] word$2$first;
    reg  [3:0] word$2$pw;
    reg  [4:0] word$2$pwh;
    wire  [25:0] word$2$addr;
    reg  [12:0] word$3$i;
    reg  [12:0] word$3$j;
    reg  [1:0] word$3$bank;
    reg  [25:0] word$3$first;
    reg  [3:0] word$3$pw;
    reg  [4:0] word$3$pwh;
    wire  [25:0] word$3$addr;
    reg  c_valid$d;
    wire  c_valid$q;
    reg  c_valid$clock;
    reg  c_second$d;
    wire  c_second$q;
    reg  c_second$clock;
    reg  c_two$d;
    wire  c_two$q;
    reg  c_two$clock;
    reg  [5:0] c_frac$d;
    wire  [5:0] c_frac$q;
    reg  c_frac$clock;
    reg  [7:0] c_alpha$d;
    wire  [7:0] c_alpha$q;
    reg  c_alpha$clock;
    reg  [7:0] c_beta$d;
    wire  [7:0] c_beta$q;
    reg  c_beta$clock;
    reg  [3:0] c_lanes$d;
    wire  [3:0] c_lanes$q;
    reg  c_lanes$clock;
    reg  [7:0] c_banks$d;
    wire  [7:0] c_banks$q;
    reg  c_banks$clock;
    reg  [25:0] c_addr$0$d;
    wire  [25:0] c_addr$0$q;
    reg  c_addr$0$clock;
    reg  [25:0] c_addr$1$d;
    wire  [25:0] c_addr$1$q;
    reg  c_addr$1$clock;
    reg  [25:0] c_addr$2$d;
    wire  [25:0] c_addr$2$q;
    reg  c_addr$2$clock;
    reg  [25:0] c_addr$3$d;
    wire  [25:0] c_addr$3$q;
    reg  c_addr$3$clock;
    
    // Local signals
    reg  magnify;
    reg  [31:0] q;
    reg  [31:0] d;
    reg  [3:0] level;
    reg  [3:0] sw;
    reg  [3:0] sh;
    reg  [5:0] ws_e;
    reg  [5:0] hs_e;
    reg  [5:0] d_e;
    reg  [5:0] side_max;
    reg  [5:0] side_min;
    reg  [5:0] side_sum;
    reg  [5:0] m_lv;
    reg  [5:0] m_2;
    reg  [5:0] e_lv;
    reg  [5:0] from_sum$0;
    reg  [5:0] from_sum$1;
    reg  [5:0] from_sum$2;
    reg  [5:0] from_sum$3;
    reg  [5:0] from_sum$4;
    reg  [5:0] from_sum$5;
    reg  [5:0] from_sum$6;
    reg  [5:0] from_sum$7;
    reg  [5:0] from_sum$8;
    reg  [5:0] from_sum$9;
    reg  [5:0] from_sum$10;
    reg  [5:0] from_sum$11;
    reg  [5:0] from_sum$12;
    reg  [5:0] from_sum$13;
    reg  [5:0] from_sum$14;
    reg  [5:0] from_sum$15;
    reg  [5:0] from_sum$16;
    reg  [5:0] from_sum$17;
    reg  [5:0] from_sum$18;
    reg  [5:0] from_sum$19;
    reg  [5:0] from_sum$20;
    reg  [5:0] from_sum$21;
    reg  [5:0] from_sum$22;
    reg  [5:0] from_sum$23;
    reg  [5:0] from_sum$24;
    reg  [5:0] from_sum$25;
    reg  [5:0] from_max$0;
    reg  [5:0] from_max$1;
    reg  [5:0] from_max$2;
    reg  [5:0] from_max$3;
    reg  [5:0] from_max$4;
    reg  [5:0] from_max$5;
    reg  [5:0] from_max$6;
    reg  [5:0] from_max$7;
    reg  [5:0] from_max$8;
    reg  [5:0] from_max$9;
    reg  [5:0] from_max$10;
    reg  [5:0] from_max$11;
    reg  [5:0] from_max$12;
    reg  [5:0] from_max$13;
    reg  [5:0] from_max$14;
    reg  [5:0] from_max$15;
    reg  [5:0] from_max$16;
    reg  [5:0] from_max$17;
    reg  [5:0] from_max$18;
    reg  [5:0] from_max$19;
    reg  [5:0] from_max$20;
    reg  [5:0] from_max$21;
    reg  [5:0] from_max$22;
    reg  [5:0] from_max$23;
    reg  [5:0] from_max$24;
    reg  [5:0] from_max$25;
    reg  [25:0] runs;
    reg  [25:0] ones;
    reg  [12:0] i_even;
    reg  [12:0] i_odd;
    reg  [12:0] j_even;
    reg  [12:0] j_odd;
    reg  has_i_even;
    reg  has_i_odd;
    reg  has_j_even;
    reg  has_j_odd;
    reg  [3:0] lane;
    
    // Sub module instances
    texture_path$unit$address$a_valid a_valid(
        .d(a_valid$d),
        .q(a_valid$q),
        .clock(a_valid$clock)
    );
    texture_path$unit$address$a_second a_second(
        .d(a_second$d),
        .q(a_second$q),
        .clock(a_second$clock)
    );
    texture_path$unit$address$a_s a_s(
        .d(a_s$d),
        .q(a_s$q),
        .clock(a_s$clock)
    );
    texture_path$unit$address$a_t a_t(
        .d(a_t$d),
        .q(a_t$q),
        .clock(a_t$clock)
    );
    texture_path$unit$address$a_two a_two(
        .d(a_two$d),
        .q(a_two$q),
        .clock(a_two$clock)
    );
    texture_path$unit$address$a_frac a_frac(
        .d(a_frac$d),
        .q(a_frac$q),
        .clock(a_frac$clock)
    );
    texture_path$unit$address$a_linear a_linear(
        .d(a_linear$d),
        .q(a_linear$q),
        .clock(a_linear$clock)
    );
    texture_path$unit$address$a_level a_level(
        .d(a_level$d),
        .q(a_level$q),
        .clock(a_level$clock)
    );
    texture_path$unit$address$a_sw a_sw(
        .d(a_sw$d),
        .q(a_sw$q),
        .clock(a_sw$clock)
    );
    texture_path$unit$address$a_sh a_sh(
        .d(a_sh$d),
        .q(a_sh$q),
        .clock(a_sh$clock)
    );
    texture_path$unit$address$a_pw a_pw(
        .d(a_pw$d),
        .q(a_pw$q),
        .clock(a_pw$clock)
    );
    texture_path$unit$address$a_ph a_ph(
        .d(a_ph$d),
        .q(a_ph$q),
        .clock(a_ph$clock)
    );
    texture_path$unit$address$across across(
        .coord(across$coord),
        .size_log2(across$size_log2),
        .linear(across$linear),
        .i0(across$i0),
        .i1(across$i1),
        .frac(across$frac)
    );
    texture_path$unit$address$up up(
        .coord(up$coord),
        .size_log2(up$size_log2),
        .linear(up$linear),
        .i0(up$i0),
        .i1(up$i1),
        .frac(up$frac)
    );
    texture_path$unit$address$b_valid b_valid(
        .d(b_valid$d),
        .q(b_valid$q),
        .clock(b_valid$clock)
    );
    texture_path$unit$address$b_second b_second(
        .d(b_second$d),
        .q(b_second$q),
        .clock(b_second$clock)
    );
    texture_path$unit$address$b_two b_two(
        .d(b_two$d),
        .q(b_two$q),
        .clock(b_two$clock)
    );
    texture_path$unit$address$b_frac b_frac(
        .d(b_frac$d),
        .q(b_frac$q),
        .clock(b_frac$clock)
    );
    texture_path$unit$address$b_sw b_sw(
        .d(b_sw$d),
        .q(b_sw$q),
        .clock(b_sw$clock)
    );
    texture_path$unit$address$b_sh b_sh(
        .d(b_sh$d),
        .q(b_sh$q),
        .clock(b_sh$clock)
    );
    texture_path$unit$address$b_pw b_pw(
        .d(b_pw$d),
        .q(b_pw$q),
        .clock(b_pw$clock)
    );
    texture_path$unit$address$b_pwh b_pwh(
        .d(b_pwh$d),
        .q(b_pwh$q),
        .clock(b_pwh$clock)
    );
    texture_path$unit$address$b_i0 b_i0(
        .d(b_i0$d),
        .q(b_i0$q),
        .clock(b_i0$clock)
    );
    texture_path$unit$address$b_i1 b_i1(
        .d(b_i1$d),
        .q(b_i1$q),
        .clock(b_i1$clock)
    );
    texture_path$unit$address$b_j0 b_j0(
        .d(b_j0$d),
        .q(b_j0$q),
        .clock(b_j0$clock)
    );
    texture_path$unit$address$b_j1 b_j1(
        .d(b_j1$d),
        .q(b_j1$q),
        .clock(b_j1$clock)
    );
    texture_path$unit$address$b_alpha b_alpha(
        .d(b_alpha$d),
        .q(b_alpha$q),
        .clock(b_alpha$clock)
    );
    texture_path$unit$address$b_beta b_beta(
        .d(b_beta$d),
        .q(b_beta$q),
        .clock(b_beta$clock)
    );
    texture_path$unit$address$b_first b_first(
        .d(b_first$d),
        .q(b_first$q),
        .clock(b_first$clock)
    );
    texture_path$unit$address$wrap$0 wrap$0(
        .i(wrap$0$i),
        .size_log2(wrap$0$size_log2),
        .mode(wrap$0$mode),
        .wrapped(wrap$0$wrapped)
    );
    texture_path$unit$address$wrap$1 wrap$1(
        .i(wrap$1$i),
        .size_log2(wrap$1$size_log2),
        .mode(wrap$1$mode),
        .wrapped(wrap$1$wrapped)
    );
    texture_path$unit$address$wrap$2 wrap$2(
        .i(wrap$2$i),
        .size_log2(wrap$2$size_log2),
        .mode(wrap$2$mode),
        .wrapped(wrap$2$wrapped)
    );
    texture_path$unit$address$wrap$3 wrap$3(
        .i(wrap$3$i),
        .size_log2(wrap$3$size_log2),
        .mode(wrap$3$mode),
        .wrapped(wrap$3$wrapped)
    );
    texture_path$unit$address$word$0 word$0(
        .i(word$0$i),
        .j(word$0$j),
        .bank(word$0$bank),
        .first(word$0$first),
        .pw(word$0$pw),
        .pwh(word$0$pwh),
        .addr(word$0$addr)
    );
    texture_path$unit$address$word$1 word$1(
        .i(word$1$i),
        .j(word$1$j),
        .bank(word$1$bank),
        .first(word$1$first),
        .pw(word$1$pw),
        .pwh(word$1$pwh),
        .addr(word$1$addr)
    );
    texture_path$unit$address$word$2 word$2(
        .i(word$2$i),
        .j(word$2$j),
        .bank(word$2$bank),
        .first(word$2$first),
        .pw(word$2$pw),
        .pwh(word$2$pwh),
        .addr(word$2$addr)
    );
    texture_path$unit$address$word$3 word$3(
        .i(word$3$i),
        .j(word$3$j),
        .bank(word$3$bank),
        .first(word$3$first),
        .pw(word$3$pw),
        .pwh(word$3$pwh),
        .addr(word$3$addr)
    );
    texture_path$unit$address$c_valid c_valid(
        .d(c_valid$d),
        .q(c_valid$q),
        .clock(c_valid$clock)
    );
    texture_path$unit$address$c_second c_second(
        .d(c_second$d),
        .q(c_second$q),
        .clock(c_second$clock)
    );
    texture_path$unit$address$c_two c_two(
        .d(c_two$d),
        .q(c_two$q),
        .clock(c_two$clock)
    );
    texture_path$unit$address$c_frac c_frac(
        .d(c_frac$d),
        .q(c_frac$q),
        .clock(c_frac$clock)
    );
    texture_path$unit$address$c_alpha c_alpha(
        .d(c_alpha$d),
        .q(c_alpha$q),
        .clock(c_alpha$clock)
    );
    texture_path$unit$address$c_beta c_beta(
        .d(c_beta$d),
        .q(c_beta$q),
        .clock(c_beta$clock)
    );
    texture_path$unit$address$c_lanes c_lanes(
        .d(c_lanes$d),
        .q(c_lanes$q),
        .clock(c_lanes$clock)
    );
    texture_path$unit$address$c_banks c_banks(
        .d(c_banks$d),
        .q(c_banks$q),
        .clock(c_banks$clock)
    );
    texture_path$unit$address$c_addr$0 c_addr$0(
        .d(c_addr$0$d),
        .q(c_addr$0$q),
        .clock(c_addr$0$clock)
    );
    texture_path$unit$address$c_addr$1 c_addr$1(
        .d(c_addr$1$d),
        .q(c_addr$1$q),
        .clock(c_addr$1$clock)
    );
    texture_path$unit$address$c_addr$2 c_addr$2(
        .d(c_addr$2$d),
        .q(c_addr$2$q),
        .clock(c_addr$2$clock)
    );
    texture_path$unit$address$c_addr$3 c_addr$3(
        .d(c_addr$3$d),
        .q(c_addr$3$q),
        .clock(c_addr$3$clock)
    );
    
    // Update code
    always @(*) begin
        a_valid$clock = clock;
        a_second$clock = clock;
        a_s$clock = clock;
        a_t$clock = clock;
        a_two$clock = clock;
        a_frac$clock = clock;
        a_linear$clock = clock;
        a_level$clock = clock;
        a_sw$clock = clock;
        a_sh$clock = clock;
        a_pw$clock = clock;
        a_ph$clock = clock;
        b_valid$clock = clock;
        b_second$clock = clock;
        b_two$clock = clock;
        b_frac$clock = clock;
        b_sw$clock = clock;
        b_sh$clock = clock;
        b_pw$clock = clock;
        b_pwh$clock = clock;
        b_i0$clock = clock;
        b_i1$clock = clock;
        b_j0$clock = clock;
        b_j1$clock = clock;
        b_alpha$clock = clock;
        b_beta$clock = clock;
        b_first$clock = clock;
        c_valid$clock = clock;
        c_second$clock = clock;
        c_two$clock = clock;
        c_frac$clock = clock;
        c_alpha$clock = clock;
        c_beta$clock = clock;
        c_lanes$clock = clock;
        c_banks$clock = clock;
        a_valid$d = a_valid$q;
        a_second$d = a_second$q;
        a_s$d = a_s$q;
        a_t$d = a_t$q;
        a_two$d = a_two$q;
        a_frac$d = a_frac$q;
        a_linear$d = a_linear$q;
        a_level$d = a_level$q;
        a_sw$d = a_sw$q;
        a_sh$d = a_sh$q;
        a_pw$d = a_pw$q;
        a_ph$d = a_ph$q;
        b_valid$d = b_valid$q;
        b_second$d = b_second$q;
        b_two$d = b_two$q;
        b_frac$d = b_frac$q;
        b_sw$d = b_sw$q;
        b_sh$d = b_sh$q;
        b_pw$d = b_pw$q;
        b_pwh$d = b_pwh$q;
        b_i0$d = b_i0$q;
        b_i1$d = b_i1$q;
        b_j0$d = b_j0$q;
        b_j1$d = b_j1$q;
        b_alpha$d = b_alpha$q;
        b_beta$d = b_beta$q;
        b_first$d = b_first$q;
        c_valid$d = c_valid$q;
        c_second$d = c_second$q;
        c_two$d = c_two$q;
        c_frac$d = c_frac$q;
        c_alpha$d = c_alpha$q;
        c_beta$d = c_beta$q;
        c_lanes$d = c_lanes$q;
        c_banks$d = c_banks$q;
        c_addr$0$clock = clock;
        c_addr$0$d = c_addr$0$q;
        c_addr$1$clock = clock;
        c_addr$1$d = c_addr$1$q;
        c_addr$2$clock = clock;
        c_addr$2$d = c_addr$2$q;
        c_addr$3$clock = clock;
        c_addr$3$d = c_addr$3$q;
        q = ((levels) & 32'hffffffff) - 32'h1;
        magnify = lambda[32'h1f] | ~|lambda;
        inp_two_levels = 1'b0;
        d = 32'h0;
        if (~magnify) begin
            if (mip == 32'h1) begin
                d = (lambda + 32'h1f) >> 32'h6;
                if (d > q) begin
                    d = q;
                end
            end
            if (mip == 32'h2) begin
                d = lambda >> 32'h6;
                if (d >= q) begin
                    d = q;
                end
                else begin
                    inp_two_levels = 1'b1;
                    if (second) begin
                        d = d + 32'h1;
                    end
                end
            end
        end
        level = d[(32'h0)+:(4)];
        sw = 32'h0;
        if (ws > level) begin
            sw = ws - level;
        end
        sh = 32'h0;
        if (hs > level) begin
            sh = hs - level;
        end
        if (en) begin
            a_valid$d = inp_valid;
            a_second$d = second;
            a_s$d = s;
            a_t$d = t;
            a_two$d = inp_two_levels;
            a_frac$d = 32'h0;
            if (inp_two_levels) begin
                a_frac$d = lambda[(32'h0)+:(6)];
            end
            a_linear$d = min_linear;
            if (magnify) begin
                a_linear$d = mag_linear;
            end
            a_level$d = level;
            a_sw$d = sw;
            a_sh$d = sh;
            a_pw$d = 32'h0;
            if (|sw) begin
                a_pw$d = sw - 32'h1;
            end
            a_ph$d = 32'h0;
            if (|sh) begin
                a_ph$d = sh - 32'h1;
            end
        end
        across$coord = a_s$q;
        across$size_log2 = a_sw$q;
        across$linear = a_linear$q;
        up$coord = a_t$q;
        up$size_log2 = a_sh$q;
        up$linear = a_linear$q;
        ws_e = ((ws) & 6'h3f);
        hs_e = ((hs) & 6'h3f);
        d_e = ((a_level$q) & 6'h3f);
        side_max = ws_e;
        side_min = hs_e;
        if (hs_e > ws_e) begin
            side_max = hs_e;
            side_min = ws_e;
        end
        side_sum = ws_e + hs_e;
        m_lv = d_e;
        if (d_e > side_min) begin
            m_lv = side_min;
        end
        m_2 = m_lv << 32'h1;
        e_lv = d_e;
        if (d_e > side_max) begin
            e_lv = side_max;
        end
        runs = 32'h0;
        from_sum$0 = side_sum - pos$0;
        from_max$0 = side_max + 32'h1 - pos$0;
        if (~from_sum$0[32'h0] & (from_sum$0 < m_2)) begin
            runs = runs | pos_bit$0;
        end
        if ((from_max$0 >= side_min) & (from_max$0 < e_lv)) begin
            runs = runs | pos_bit$0;
        end
        from_sum$1 = side_sum - pos$1;
        from_max$1 = side_max + 32'h1 - pos$1;
        if (~from_sum$1[32'h0] & (from_sum$1 < m_2)) begin
            runs = runs | pos_bit$1;
        end
        if ((from_max$1 >= side_min) & (from_max$1 < e_lv)) begin
            runs = runs | pos_bit$1;
        end
        from_sum$2 = side_sum - pos$2;
        from_max$2 = side_max + 32'h1 - pos$2;
        if (~from_sum$2[32'h0] & (from_sum$2 < m_2)) begin
            runs = runs | pos_bit$2;
        end
        if ((from_max$2 >= side_min) & (from_max$2 < e_lv)) begin
            runs = runs | pos_bit$2;
        end
        from_sum$3 = side_sum - pos$3;
        from_max$3 = side_max + 32'h1 - pos$3;
        if (~from_sum$3[32'h0] & (from_sum$3 < m_2)) begin
            runs = runs | pos_bit$3;
        end
        if ((from_max$3 >= side_min) & (from_max$3 < e_lv)) begin
            runs = runs | pos_bit$3;
        end
        from_sum$4 = side_sum - pos$4;
        from_max$4 = side_max + 32'h1 - pos$4;
        if (~from_sum$4[32'h0] & (from_sum$4 < m_2)) begin
            runs = runs | pos_bit$4;
        end
        if ((from_max$4 >= side_min) & (from_max$4 < e_lv)) begin
            runs = runs | pos_bit$4;
        end
        from_sum$5 = side_sum - pos$5;
        from_max$5 = side_max + 32'h1 - pos$5;
        if (~from_sum$5[32'h0] & (from_sum$5 < m_2)) begin
            runs = runs | pos_bit$5;
        end
        if ((from_max$5 >= side_min) & (from_max$5 < e_lv)) begin
            runs = runs | pos_bit$5;
        end
        from_sum$6 = side_sum - pos$6;
        from_max$6 = side_max + 32'h1 - pos$6;
        if (~from_sum$6[32'h0] & (from_sum$6 < m_2)) begin
            runs = runs | pos_bit$6;
        end
        if ((from_max$6 >= side_min) & (from_max$6 < e_lv)) begin
            runs = runs | pos_bit$6;
        end
        from_sum$7 = side_sum - pos$7;
        from_max$7 = side_max + 32'h1 - pos$7;
        if (~from_sum$7[32'h0] & (from_sum$7 < m_2)) begin
            runs = runs | pos_bit$7;
        end
        if ((from_max$7 >= side_min) & (from_max$7 < e_lv)) begin
            runs = runs | pos_bit$7;
        end
        from_sum$8 = side_sum - pos$8;
        from_max$8 = side_max + 32'h1 - pos$8;
        if (~from_sum$8[32'h0] & (from_sum$8 < m_2)) begin
            runs = runs | pos_bit$8;
        end
        if ((from_max$8 >= side_min) & (from_max$8 < e_lv)) begin
            runs = runs | pos_bit$8;
        end
        from_sum$9 = side_sum - pos$9;
        from_max$9 = side_max + 32'h1 - pos$9;
        if (~from_sum$9[32'h0] & (from_sum$9 < m_2)) begin
            runs = runs | pos_bit$9;
        end
        if ((from_max$9 >= side_min) & (from_max$9 < e_lv)) begin
            runs = runs | pos_bit$9;
        end
        from_sum$10 = side_sum - pos$10;
        from_max$10 = side_max + 32'h1 - pos$10;
        if (~from_sum$10[32'h0] & (from_sum$10 < m_2)) begin
            runs = runs | pos_bit$10;
        end
        if ((from_max$10 >= side_min) & (from_max$10 < e_lv)) begin
            runs = runs | pos_bit$10;
        end
        from_sum$11 = side_sum - pos$11;
        from_max$11 = side_max + 32'h1 - pos$11;
        if (~from_sum$11[32'h0] & (from_sum$11 < m_2)) begin
            runs = runs | pos_bit$11;
        end
        if ((from_max$11 >= side_min) & (from_max$11 < e_lv)) begin
            runs = runs | pos_bit$11;
        end
        from_sum$12 = side_sum - pos$12;
        from_max$12 = side_max + 32'h1 - pos$12;
        if (~from_sum$12[32'h0] & (from_sum$12 < m_2)) begin
            runs = runs | pos_bit$12;
        end
        if ((from_max$12 >= side_min) & (from_max$12 < e_lv)) begin
            runs = runs | pos_bit$12;
        end
        from_sum$13 = side_sum - pos$13;
        from_max$13 = side_max + 32'h1 - pos$13;
        if (~from_sum$13[32'h0] & (from_sum$13 < m_2)) begin
            runs = runs | pos_bit$13;
        end
        if ((from_max$13 >= side_min) & (from_max$13 < e_lv)) begin
            runs = runs | pos_bit$13;
        end
        from_sum$14 = side_sum - pos$14;
        from_max$14 = side_max + 32'h1 - pos$14;
        if (~from_sum$14[32'h0] & (from_sum$14 < m_2)) begin
            runs = runs | pos_bit$14;
        end
        if ((from_max$14 >= side_min) & (from_max$14 < e_lv)) begin
            runs = runs | pos_bit$14;
        end
        from_sum$15 = side_sum - pos$15;
        from_max$15 = side_max + 32'h1 - pos$15;
        if (~from_sum$15[32'h0] & (from_sum$15 < m_2)) begin
            runs = runs | pos_bit$15;
        end
        if ((from_max$15 >= side_min) & (from_max$15 < e_lv)) begin
            runs = runs | pos_bit$15;
        end
        from_sum$16 = side_sum - pos$16;
        from_max$16 = side_max + 32'h1 - pos$16;
        if (~from_sum$16[32'h0] & (from_sum$16 < m_2)) begin
            runs = runs | pos_bit$16;
        end
        if ((from_max$16 >= side_min) & (from_max$16 < e_lv)) begin
            runs = runs | pos_bit$16;
        end
        from_sum$17 = side_sum - pos$17;
        from_max$17 = side_max + 32'h1 - pos$17;
        if (~from_sum$17[32'h0] & (from_sum$17 < m_2)) begin
            runs = runs | pos_bit$17;
        end
        if ((from_max$17 >= side_min) & (from_max$17 < e_lv)) begin
            runs = runs | pos_bit$17;
        end
        from_sum$18 = side_sum - pos$18;
        from_max$18 = side_max + 32'h1 - pos$18;
        if (~from_sum$18[32'h0] & (from_sum$18 < m_2)) begin
            runs = runs | pos_bit$18;
        end
        if ((from_max$18 >= side_min) & (from_max$18 < e_lv)) begin
            runs = runs | pos_bit$18;
        end
        from_sum$19 = side_sum - pos$19;
        from_max$19 = side_max + 32'h1 - pos$19;
        if (~from_sum$19[32'h0] & (from_sum$19 < m_2)) begin
            runs = runs | pos_bit$19;
        end
        if ((from_max$19 >= side_min) & (from_max$19 < e_lv)) begin
            runs = runs | pos_bit$19;
        end
        from_sum$20 = side_sum - pos$20;
        from_max$20 = side_max + 32'h1 - pos$20;
        if (~from_sum$20[32'h0] & (from_sum$20 < m_2)) begin
            runs = runs | pos_bit$20;
        end
        if ((from_max$20 >= side_min) & (from_max$20 < e_lv)) begin
            runs = runs | pos_bit$20;
        end
        from_sum$21 = side_sum - pos$21;
        from_max$21 = side_max + 32'h1 - pos$21;
        if (~from_sum$21[32'h0] & (from_sum$21 < m_2)) begin
            runs = runs | pos_bit$21;
        end
        if ((from_max$21 >= side_min) & (from_max$21 < e_lv)) begin
            runs = runs | pos_bit$21;
        end
        from_sum$22 = side_sum - pos$22;
        from_max$22 = side_max + 32'h1 - pos$22;
        if (~from_sum$22[32'h0] & (from_sum$22 < m_2)) begin
            runs = runs | pos_bit$22;
        end
        if ((from_max$22 >= side_min) & (from_max$22 < e_lv)) begin
            runs = runs | pos_bit$22;
        end
        from_sum$23 = side_sum - pos$23;
        from_max$23 = side_max + 32'h1 - pos$23;
        if (~from_sum$23[32'h0] & (from_sum$23 < m_2)) begin
            runs = runs | pos_bit$23;
        end
        if ((from_max$23 >= side_min) & (from_max$23 < e_lv)) begin
            runs = runs | pos_bit$23;
        end
        from_sum$24 = side_sum - pos$24;
        from_max$24 = side_max + 32'h1 - pos$24;
        if (~from_sum$24[32'h0] & (from_sum$24 < m_2)) begin
            runs = runs | pos_bit$24;
        end
        if ((from_max$24 >= side_min) & (from_max$24 < e_lv)) begin
            runs = runs | pos_bit$24;
        end
        from_sum$25 = side_sum - pos$25;
        from_max$25 = side_max + 32'h1 - pos$25;
        if (~from_sum$25[32'h0] & (from_sum$25 < m_2)) begin
            runs = runs | pos_bit$25;
        end
        if ((from_max$25 >= side_min) & (from_max$25 < e_lv)) begin
            runs = runs | pos_bit$25;
        end
        ones = 32'h0;
        if (d_e > side_max) begin
            ones = ((d_e - side_max) & 26'h3ffffff) << 32'h2;
        end
        if (en) begin
            b_valid$d = a_valid$q;
            b_second$d = a_second$q;
            b_two$d = a_two$q;
            b_frac$d = a_frac$q;
            b_sw$d = a_sw$q;
            b_sh$d = a_sh$q;
            b_pw$d = a_pw$q;
            b_pwh$d = ((a_pw$q) & 5'h1f) + ((a_ph$q) & 5'h1f);
            b_i0$d = across$i0;
            b_i1$d = across$i1;
            b_j0$d = up$i0;
            b_j1$d = up$i1;
            b_alpha$d = across$frac;
            b_beta$d = up$frac;
            b_first$d = base + runs + ones;
        end
        wrap$0$i = b_i0$q;
        wrap$1$i = b_i1$q;
        wrap$2$i = b_j0$q;
        wrap$3$i = b_j1$q;
        wrap$0$size_log2 = b_sw$q;
        wrap$1$size_log2 = b_sw$q;
        wrap$2$size_log2 = b_sh$q;
        wrap$3$size_log2 = b_sh$q;
        wrap$0$mode = wrap_s;
        wrap$1$mode = wrap_s;
        wrap$2$mode = wrap_t;
        wrap$3$mode = wrap_t;
        i_even = wrap$1$wrapped;
        i_odd = wrap$0$wrapped;
        if (~wrap$0$wrapped[32'h0]) begin
            i_even = wrap$0$wrapped;
            i_odd = wrap$1$wrapped;
        end
        j_even = wrap$3$wrapped;
        j_odd = wrap$2$wrapped;
        if (~wrap$2$wrapped[32'h0]) begin
            j_even = wrap$2$wrapped;
            j_odd = wrap$3$wrapped;
        end
        has_i_even = ~wrap$0$wrapped[32'h0] | ~wrap$1$wrapped[32'h0];
        has_i_odd = wrap$0$wrapped[32'h0] | wrap$1$wrapped[32'h0];
        has_j_even = ~wrap$2$wrapped[32'h0] | ~wrap$3$wrapped[32'h0];
        has_j_odd = wrap$2$wrapped[32'h0] | wrap$3$wrapped[32'h0];
        word$0$i = i_even;
        word$1$i = i_odd;
        word$2$i = i_even;
        word$3$i = i_odd;
        word$0$j = j_even;
        word$1$j = j_even;
        word$2$j = j_odd;
        word$3$j = j_odd;
        lane = 32'h0;
        if (has_i_even & has_j_even) begin
            lane = lane | lane_bit$0;
        end
        if (has_i_odd & has_j_even) begin
            lane = lane | lane_bit$1;
        end
        if (has_i_even & has_j_odd) begin
            lane = lane | lane_bit$2;
        end
        if (has_i_odd & has_j_odd) begin
            lane = lane | lane_bit$3;
        end
        word$0$bank = bank_id$0;
        word$0$first = b_first$q;
        word$0$pw = b_pw$q;
        word$0$pwh = b_pwh$q;
        word$1$bank = bank_id$1;
        word$1$first = b_first$q;
        word$1$pw = b_pw$q;
        word$1$pwh = b_pwh$q;
        word$2$bank = bank_id$2;
        word$2$first = b_first$q;
        word$2$pw = b_pw$q;
        word$2$pwh = b_pwh$q;
        word$3$bank = bank_id$3;
        word$3$first = b_first$q;
        word$3$pw = b_pw$q;
        word$3$pwh = b_pwh$q;
        if (en) begin
            c_valid$d = b_valid$q;
            c_second$d = b_second$q;
            c_two$d = b_two$q;
            c_frac$d = b_frac$q;
            c_alpha$d = b_alpha$q;
            c_beta$d = b_beta$q;
            c_banks$d = ((wrap$0$wrapped[(32'h0)+:(1)]) & 8'hff) | (((wrap$2$wrapped[(32'h0)+:(1)]) & 8'hff) << 32'h1) | (((wrap$1$wrapped[(32'h0)+:(1)]) & 8'hff) << 32'h2) | (((wrap$2$wrapped[(32'h0)+:(1)]) & 8'hff) << 32'h3) | (((wrap$0$wrapped[(32'h0)+:(1)]) & 8'hff) << 32'h4) | (((wrap$3$wrapped[(32'h0)+:(1)]) & 8'hff) << 32'h5) | (((wrap$1$wrapped[(32'h0)+:(1)]) & 8'hff) << 32'h6) | (((wrap$3$wrapped[(32'h0)+:(1)]) & 8'hff) << 32'h7);
            c_lanes$d = lane;
            c_addr$0$d = 32'h0;
            if (|(lane & lane_bit$0)) begin
                c_addr$0$d = word$0$addr;
            end
            c_addr$1$d = 32'h0;
            if (|(lane & lane_bit$1)) begin
                c_addr$1$d = word$1$addr;
            end
            c_addr$2$d = 32'h0;
            if (|(lane & lane_bit$2)) begin
                c_addr$2$d = word$2$addr;
            end
            c_addr$3$d = 32'h0;
            if (|(lane & lane_bit$3)) begin
                c_addr$3$d = word$3$addr;
            end
        end
        out_valid = c_valid$q;
        out_second = c_second$q;
        two_levels = c_two$q;
        frac = c_frac$q;
        alpha = c_alpha$q;
        beta = c_beta$q;
        lanes = c_lanes$q;
        banks = c_banks$q;
        addr0 = c_addr$0$q;
        addr1 = c_addr$1$q;
        addr2 = c_addr$2$q;
        addr3 = c_addr$3$q;
    end
    
endmodule // texture_path$unit$address


module texture_path$unit$address$a_frac(d,q,clock);
    
    // Module arguments
    input wire  [5:0] d;
    output reg  [5:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 6'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$address$a_frac


module texture_path$unit$address$a_level(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$address$a_level


module texture_path$unit$address$a_linear(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$address$a_linear


module texture_path$unit$address$a_ph(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$address$a_ph


module texture_path$unit$address$a_pw(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$address$a_pw


module texture_path$unit$address$a_s(d,q,clock);
    
    // Module arguments
    input wire  [28:0] d;
    output reg  [28:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 29'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$address$a_s


module texture_path$unit$address$a_second(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$address$a_second


module texture_path$unit$address$a_sh(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$address$a_sh


module texture_path$unit$address$a_sw(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$address$a_sw


module texture_path$unit$address$a_t(d,q,clock);
    
    // Module arguments
    input wire  [28:0] d;
    output reg  [28:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 29'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$address$a_t


module texture_path$unit$address$a_two(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$address$a_two


module texture_path$unit$address$a_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$address$a_valid


module texture_path$unit$address$across(coord,size_log2,linear,i0,i1,frac);
    
    // Module arguments
    input wire  [28:0] coord;
    input wire  [3:0] size_log2;
    input wire  linear;
    output reg  [21:0] i0;
    output reg  [21:0] i1;
    output reg  [7:0] frac;
    
    // Local signals
    reg  [29:0] wide;
    reg  [29:0] u;
    reg  [21:0] top;
    
    // Update code
    always @(*) begin
        wide = ((coord) & 30'h3fffffff);
        if (coord[32'h1c]) begin
            wide = ((coord) & 30'h3fffffff) | ((32'h20000000) & 30'h3fffffff);
        end
        u = wide >> (((32'hc) & 30'h3fffffff) - ((size_log2) & 30'h3fffffff));
        if (coord[32'h1c]) begin
            u = (wide >> (((32'hc) & 30'h3fffffff) - ((size_log2) & 30'h3fffffff))) | ~(((32'h3fffffff) & 30'h3fffffff) >> (((32'hc) & 30'h3fffffff) - ((size_log2) & 30'h3fffffff)));
        end
        top = u[(32'h8)+:(22)];
        i0 = top;
        i1 = top;
        frac = 32'h0;
        if (linear) begin
            i1 = top + 32'h1;
            if (~u[32'h7]) begin
                i0 = top - 32'h1;
                i1 = top;
            end
            frac = u[(32'h0)+:(8)] ^ ((32'h80) & 8'hff);
        end
    end
    
endmodule // texture_path$unit$address$across


module texture_path$unit$address$b_alpha(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$address$b_alpha


module texture_path$unit$address$b_beta(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$address$b_beta


module texture_path$unit$address$b_first(d,q,clock);
    
    // Module arguments
    input wire  [25:0] d;
    output reg  [25:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 26'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$address$b_first


module texture_path$unit$address$b_frac(d,q,clock);
    
    // Module arguments
    input wire  [5:0] d;
    output reg  [5:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 6'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$address$b_frac


module texture_path$unit$address$b_i0(d,q,clock);
    
    // Module arguments
    input wire  [21:0] d;
    output reg  [21:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 22'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$address$b_i0


module texture_path$unit$address$b_i1(d,q,clock);
    
    // Module arguments
    input wire  [21:0] d;
    output reg  [21:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 22'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$address$b_i1


module texture_path$unit$address$b_j0(d,q,clock);
    
    // Module arguments
    input wire  [21:0] d;
    output reg  [21:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 22'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$address$b_j0


module texture_path$unit$address$b_j1(d,q,clock);
    
    // Module arguments
    input wire  [21:0] d;
    output reg  [21:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 22'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$address$b_j1


module texture_path$unit$address$b_pw(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$address$b_pw


module texture_path$unit$address$b_pwh(d,q,clock);
    
    // Module arguments
    input wire  [4:0] d;
    output reg  [4:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 5'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$address$b_pwh


module texture_path$unit$address$b_second(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$address$b_second


module texture_path$unit$address$b_sh(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$address$b_sh


module texture_path$unit$address$b_sw(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$address$b_sw


module texture_path$unit$address$b_two(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$address$b_two


module texture_path$unit$address$b_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$address$b_valid


module texture_path$unit$address$c_addr$0(d,q,clock);
    
    // Module arguments
    input wire  [25:0] d;
    output reg  [25:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 26'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$address$c_addr$0


module texture_path$unit$address$c_addr$1(d,q,clock);
    
    // Module arguments
    input wire  [25:0] d;
    output reg  [25:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 26'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$address$c_addr$1


module texture_path$unit$address$c_addr$2(d,q,clock);
    
    // Module arguments
    input wire  [25:0] d;
    output reg  [25:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 26'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$address$c_addr$2


module texture_path$unit$address$c_addr$3(d,q,clock);
    
    // Module arguments
    input wire  [25:0] d;
    output reg  [25:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 26'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$address$c_addr$3


module texture_path$unit$address$c_alpha(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$address$c_alpha


module texture_path$unit$address$c_banks(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$address$c_banks


module texture_path$unit$address$c_beta(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$address$c_beta


module texture_path$unit$address$c_frac(d,q,clock);
    
    // Module arguments
    input wire  [5:0] d;
    output reg  [5:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 6'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$address$c_frac


module texture_path$unit$address$c_lanes(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$address$c_lanes


module texture_path$unit$address$c_second(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$address$c_second


module texture_path$unit$address$c_two(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$address$c_two


module texture_path$unit$address$c_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$address$c_valid


module texture_path$unit$address$up(coord,size_log2,linear,i0,i1,frac);
    
    // Module arguments
    input wire  [28:0] coord;
    input wire  [3:0] size_log2;
    input wire  linear;
    output reg  [21:0] i0;
    output reg  [21:0] i1;
    output reg  [7:0] frac;
    
    // Local signals
    reg  [29:0] wide;
    reg  [29:0] u;
    reg  [21:0] top;
    
    // Update code
    always @(*) begin
        wide = ((coord) & 30'h3fffffff);
        if (coord[32'h1c]) begin
            wide = ((coord) & 30'h3fffffff) | ((32'h20000000) & 30'h3fffffff);
        end
        u = wide >> (((32'hc) & 30'h3fffffff) - ((size_log2) & 30'h3fffffff));
        if (coord[32'h1c]) begin
            u = (wide >> (((32'hc) & 30'h3fffffff) - ((size_log2) & 30'h3fffffff))) | ~(((32'h3fffffff) & 30'h3fffffff) >> (((32'hc) & 30'h3fffffff) - ((size_log2) & 30'h3fffffff)));
        end
        top = u[(32'h8)+:(22)];
        i0 = top;
        i1 = top;
        frac = 32'h0;
        if (linear) begin
            i1 = top + 32'h1;
            if (~u[32'h7]) begin
                i0 = top - 32'h1;
                i1 = top;
            end
            frac = u[(32'h0)+:(8)] ^ ((32'h80) & 8'hff);
        end
    end
    
endmodule // texture_path$unit$address$up


module texture_path$unit$address$word$0(i,j,bank,first,pw,pwh,addr);
    
    // Module arguments
    input wire  [12:0] i;
    input wire  [12:0] j;
    input wire  [1:0] bank;
    input wire  [25:0] first;
    input wire  [3:0] pw;
    input wire  [4:0] pwh;
    output reg  [25:0] addr;
    
    // Local signals
    reg  [25:0] field;
    
    // Update code
    always @(*) begin
        field = (((bank) & 26'h3ffffff) << ((pwh) & 26'h3ffffff)) | (((j >> 32'h1) & 26'h3ffffff) << ((pw) & 26'h3ffffff)) | ((i >> 32'h1) & 26'h3ffffff);
        addr = first + field;
    end
    
endmodule // texture_path$unit$address$word$0


module texture_path$unit$address$word$1(i,j,bank,first,pw,pwh,addr);
    
    // Module arguments
    input wire  [12:0] i;
    input wire  [12:0] j;
    input wire  [1:0] bank;
    input wire  [25:0] first;
    input wire  [3:0] pw;
    input wire  [4:0] pwh;
    output reg  [25:0] addr;
    
    // Local signals
    reg  [25:0] field;
    
    // Update code
    always @(*) begin
        field = (((bank) & 26'h3ffffff) << ((pwh) & 26'h3ffffff)) | (((j >> 32'h1) & 26'h3ffffff) << ((pw) & 26'h3ffffff)) | ((i >> 32'h1) & 26'h3ffffff);
        addr = first + field;
    end
    
endmodule // texture_path$unit$address$word$1


module texture_path$unit$address$word$2(i,j,bank,first,pw,pwh,addr);
    
    // Module arguments
    input wire  [12:0] i;
    input wire  [12:0] j;
    input wire  [1:0] bank;
    input wire  [25:0] first;
    input wire  [3:0] pw;
    input wire  [4:0] pwh;
    output reg  [25:0] addr;
    
    // Local signals
    reg  [25:0] field;
    
    // Update code
    always @(*) begin
        field = (((bank) & 26'h3ffffff) << ((pwh) & 26'h3ffffff)) | (((j >> 32'h1) & 26'h3ffffff) << ((pw) & 26'h3ffffff)) | ((i >> 32'h1) & 26'h3ffffff);
        addr = first + field;
    end
    
endmodule // texture_path$unit$address$word$2


module texture_path$unit$address$word$3(i,j,bank,first,pw,pwh,addr);
    
    // Module arguments
    input wire  [12:0] i;
    input wire  [12:0] j;
    input wire  [1:0] bank;
    input wire  [25:0] first;
    input wire  [3:0] pw;
    input wire  [4:0] pwh;
    output reg  [25:0] addr;
    
    // Local signals
    reg  [25:0] field;
    
    // Update code
    always @(*) begin
        field = (((bank) & 26'h3ffffff) << ((pwh) & 26'h3ffffff)) | (((j >> 32'h1) & 26'h3ffffff) << ((pw) & 26'h3ffffff)) | ((i >> 32'h1) & 26'h3ffffff);
        addr = first + field;
    end
    
endmodule // texture_path$unit$address$word$3


module texture_path$unit$address$wrap$0(i,size_log2,mode,wrapped);
    
    // Module arguments
    input wire  [21:0] i;
    input wire  [3:0] size_log2;
    input wire  [1:0] mode;
    output reg  [12:0] wrapped;
    
    // Local signals
    reg  [21:0] n;
    reg  [21:0] mask;
    reg  [21:0] low;
    reg  [21:0] high;
    
    // Update code
    always @(*) begin
        n = ((32'h1) & 22'h3fffff) << ((size_log2) & 22'h3fffff);
        mask = ~(((32'h3fffff) & 22'h3fffff) << ((size_log2) & 22'h3fffff));
        low = i & mask;
        high = i & ~mask;
        wrapped = ((low) & 13'h1fff);
        if ((mode == 32'h1) & |(i & n)) begin
            wrapped = ((~i & mask) & 13'h1fff);
        end
        if (mode == 32'h2) begin
            if (i[32'h15]) begin
                wrapped = 32'h0;
            end
            else if (|high) begin
                wrapped = ((mask) & 13'h1fff);
            end
        end
    end
    
endmodule // texture_path$unit$address$wrap$0


module texture_path$unit$address$wrap$1(i,size_log2,mode,wrapped);
    
    // Module arguments
    input wire  [21:0] i;
    input wire  [3:0] size_log2;
    input wire  [1:0] mode;
    output reg  [12:0] wrapped;
    
    // Local signals
    reg  [21:0] n;
    reg  [21:0] mask;
    reg  [21:0] low;
    reg  [21:0] high;
    
    // Update code
    always @(*) begin
        n = ((32'h1) & 22'h3fffff) << ((size_log2) & 22'h3fffff);
        mask = ~(((32'h3fffff) & 22'h3fffff) << ((size_log2) & 22'h3fffff));
        low = i & mask;
        high = i & ~mask;
        wrapped = ((low) & 13'h1fff);
        if ((mode == 32'h1) & |(i & n)) begin
            wrapped = ((~i & mask) & 13'h1fff);
        end
        if (mode == 32'h2) begin
            if (i[32'h15]) begin
                wrapped = 32'h0;
            end
            else if (|high) begin
                wrapped = ((mask) & 13'h1fff);
            end
        end
    end
    
endmodule // texture_path$unit$address$wrap$1


module texture_path$unit$address$wrap$2(i,size_log2,mode,wrapped);
    
    // Module arguments
    input wire  [21:0] i;
    input wire  [3:0] size_log2;
    input wire  [1:0] mode;
    output reg  [12:0] wrapped;
    
    // Local signals
    reg  [21:0] n;
    reg  [21:0] mask;
    reg  [21:0] low;
    reg  [21:0] high;
    
    // Update code
    always @(*) begin
        n = ((32'h1) & 22'h3fffff) << ((size_log2) & 22'h3fffff);
        mask = ~(((32'h3fffff) & 22'h3fffff) << ((size_log2) & 22'h3fffff));
        low = i & mask;
        high = i & ~mask;
        wrapped = ((low) & 13'h1fff);
        if ((mode == 32'h1) & |(i & n)) begin
            wrapped = ((~i & mask) & 13'h1fff);
        end
        if (mode == 32'h2) begin
            if (i[32'h15]) begin
                wrapped = 32'h0;
            end
            else if (|high) begin
                wrapped = ((mask) & 13'h1fff);
            end
        end
    end
    
endmodule // texture_path$unit$address$wrap$2


module texture_path$unit$address$wrap$3(i,size_log2,mode,wrapped);
    
    // Module arguments
    input wire  [21:0] i;
    input wire  [3:0] size_log2;
    input wire  [1:0] mode;
    output reg  [12:0] wrapped;
    
    // Local signals
    reg  [21:0] n;
    reg  [21:0] mask;
    reg  [21:0] low;
    reg  [21:0] high;
    
    // Update code
    always @(*) begin
        n = ((32'h1) & 22'h3fffff) << ((size_log2) & 22'h3fffff);
        mask = ~(((32'h3fffff) & 22'h3fffff) << ((size_log2) & 22'h3fffff));
        low = i & mask;
        high = i & ~mask;
        wrapped = ((low) & 13'h1fff);
        if ((mode == 32'h1) & |(i & n)) begin
            wrapped = ((~i & mask) & 13'h1fff);
        end
        if (mode == 32'h2) begin
            if (i[32'h15]) begin
                wrapped = 32'h0;
            end
            else if (|high) begin
                wrapped = ((mask) & 13'h1fff);
            end
        end
    end
    
endmodule // texture_path$unit$address$wrap$3


module texture_path$unit$cache(clock,inp_valid,inp_ready,inp_en,inp_addr0,inp_addr1,inp_addr2,inp_addr3,inp_side,inp_flush,out_valid,out_ready,out_data0,out_data1,out_data2,out_data3,out_side,mem$valid,mem$addr,mem$ack,mem$rvalid,mem$rdata,counters$hits,counters$misses,counters$fills);
    
    // Module arguments
    input wire  clock;
    input wire  inp_valid;
    output reg  inp_ready;
    input wire  [3:0] inp_en;
    input wire  [25:0] inp_addr0;
    input wire  [25:0] inp_addr1;
    input wire  [25:0] inp_addr2;
    input wire  [25:0] inp_addr3;
    input wire  [63:0] inp_side;
    input wire  inp_flush;
    output reg  out_valid;
    input wire  out_ready;
    output reg  [31:0] out_data0;
    output reg  [31:0] out_data1;
    output reg  [31:0] out_data2;
    output reg  [31:0] out_data3;
    output reg  [63:0] out_side;
    output reg  mem$valid;
    output reg  [25:0] mem$addr;
    input wire  mem$ack;
    input wire  mem$rvalid;
    input wire  [31:0] mem$rdata;
    output reg  [31:0] counters$hits;
    output reg  [31:0] counters$misses;
    output reg  [31:0] counters$fills;
    
    // Constant declarations
    localparam  word_last = 8'h3;
    localparam  line_base = 26'h3fffffc;
    
    // Stub signals
    reg  banks$0$clock;
    reg  [7:0] banks$0$rd_addr;
    reg  [25:0] banks$0$addr;
    reg  banks$0$fill;
    reg  [7:0] banks$0$word;
    reg  [31:0] banks$0$wdata;
    reg  banks$0$last;
    reg  banks$0$clear;
    reg  [5:0] banks$0$clear_set;
    wire  banks$0$hit;
    wire  [31:0] banks$0$data;
    reg  banks$1$clock;
    reg  [7:0] banks$1$rd_addr;
    reg  [25:0] banks$1$addr;
    reg  banks$1$fill;
    reg  [7:0] banks$1$word;
    reg  [31:0] banks$1$wdata;
    reg  banks$1$last;
    reg  banks$1$clear;
    reg  [5:0] banks$1$clear_set;
    wire  banks$1$hit;
    wire  [31:0] banks$1$data;
    reg  banks$2$clock;
    reg  [7:0] banks$2$rd_addr;
    reg  [25:0] banks$2$addr;
    reg  banks$2$fill;
    reg  [7:0] banks$2$word;
    reg  [31:0] banks$2$wdata;
    reg  banks$2$last;
    reg  banks$2$clear;
    reg  [5:0] banks$2$clear_set;
    wire  banks$2$hit;
    wire  [31:0] banks$2$data;
    reg  banks$3$clock;
    reg  [7:0] banks$3$rd_addr;
    reg  [25:0] banks$3$addr;
    reg  banks$3$fill;
    reg  [7:0] banks$3$word;
    reg  [31:0] banks$3$wdata;
    reg  banks$3$last;
    reg  banks$3$clear;
    reg  [5:0] banks$3$clear_set;
    wire  banks$3$hit;
    wire  [31:0] banks$3$data;
    reg  [1:0] st$d;
    wire  [1:0] st$q;
    reg  st$clock;
    reg  [5:0] clr$d;
    wire  [5:0] clr$q;
    reg  clr$clock;
    reg  flush_pend$d;
    wire  flush_pend$q;
    reg  flush_pend$clock;
    reg  s1_valid$d;
    wire  s1_valid$q;
    reg  s1_valid$clock;
    reg  s1_fresh$d;
    wire  s1_fresh$q;
    reg  s1_fresh$clock;
    reg  [3:0] s1_en$d;
    wire  [3:0] s1_en$q;
    reg  s1_en$clock;
    reg  [25:0] s1_addr$0$d;
    wire  [25:0] s1_addr$0$q;
    reg  s1_addr$0$clock;
    reg  [25:0] s1_addr$1$d;
    wire  [25:0] s1_addr$1$q;
    reg  s1_addr$1$clock;
    reg  [25:0] s1_addr$2$d;
    wire  [25:0] s1_addr$2$q;
    reg  s1_addr$2$clock;
    reg  [25:0] s1_addr$3$d;
    wire  [25:0] s1_addr$3$q;
    reg  s1_addr$3$clock;
    reg  [63:0] s1_side$d;
    wire  [63:0] s1_side$q;
    reg  s1_side$clock;
    reg  o_valid$d;
    wire  o_valid$q;
    reg  o_valid$clock;
    reg  [31:0] o_data$0$d;
    wire  [31:0] o_data$0$q;
    reg  o_data$0$clock;
    reg  [31:0] o_data$1$d;
    wire  [31:0] o_data$1$q;
    reg  o_data$1$clock;
    reg  [31:0] o_data$2$d;
    wire  [31:0] o_data$2$q;
    reg  o_data$2$clock;
    reg  [31:0] o_data$3$d;
    wire  [31:0] o_data$3$q;
    reg  o_data$3$clock;
    reg  [63:0] o_side$d;
    wire  [63:0] o_side$q;
    reg  o_side$clock;
    reg  [3:0] iss_mask$d;
    wire  [3:0] iss_mask$q;
    reg  iss_mask$clock;
    reg  [7:0] iss_word$d;
    wire  [7:0] iss_word$q;
    reg  iss_word$clock;
    reg  [3:0] rcv_mask$d;
    wire  [3:0] rcv_mask$q;
    reg  rcv_mask$clock;
    reg  [7:0] rcv_word$d;
    wire  [7:0] rcv_word$q;
    reg  rcv_word$clock;
    reg  [31:0] hits_r$d;
    wire  [31:0] hits_r$q;
    reg  hits_r$clock;
    reg  [31:0] misses_r$d;
    wire  [31:0] misses_r$q;
    reg  misses_r$clock;
    reg  [31:0] fills_r$d;
    wire  [31:0] fills_r$q;
    reg  fills_r$clock;
    
    // Local signals
    reg  run;
    reg  all_hit;
    reg  [3:0] miss_mask;
    reg  [31:0] n_hit;
    reg  [31:0] n_miss;
    reg  o_free;
    reg  s1_go;
    reg  pending;
    reg  take;
    reg  [1:0] iss_lane;
    reg  [25:0] iss_addr;
    reg  [1:0] rcv_lane;
    reg  rcv;
    reg  rcv_last;
    reg  [3:0] rcv_rest;
    
    // Sub module instances
    texture_path$unit$cache$banks$0 banks$0(
        .clock(banks$0$clock),
        .rd_addr(banks$0$rd_addr),
        .addr(banks$0$addr),
        .fill(banks$0$fill),
        .word(banks$0$word),
        .wdata(banks$0$wdata),
        .last(banks$0$last),
        .clear(banks$0$clear),
        .clear_set(banks$0$clear_set),
        .hit(banks$0$hit),
        .data(banks$0$data)
    );
    texture_path$unit$cache$banks$1 banks$1(
        .clock(banks$1$clock),
        .rd_addr(banks$1$rd_addr),
        .addr(banks$1$addr),
        .fill(banks$1$fill),
        .word(banks$1$word),
        .wdata(banks$1$wdata),
        .last(banks$1$last),
        .clear(banks$1$clear),
        .clear_set(banks$1$clear_set),
        .hit(banks$1$hit),
        .data(banks$1$data)
    );
    texture_path$unit$cache$banks$2 banks$2(
        .clock(banks$2$clock),
        .rd_addr(banks$2$rd_addr),
        .addr(banks$2$addr),
        .fill(banks$2$fill),
        .word(banks$2$word),
        .wdata(banks$2$wdata),
        .last(banks$2$last),
        .clear(banks$2$clear),
        .clear_set(banks$2$clear_set),
        .hit(banks$2$hit),
        .data(banks$2$data)
    );
    texture_path$unit$cache$banks$3 banks$3(
        .clock(banks$3$clock),
        .rd_addr(banks$3$rd_addr),
        .addr(banks$3$addr),
        .fill(banks$3$fill),
        .word(banks$3$word),
        .wdata(banks$3$wdata),
        .last(banks$3$last),
        .clear(banks$3$clear),
        .clear_set(banks$3$clear_set),
        .hit(banks$3$hit),
        .data(banks$3$data)
    );
    texture_path$unit$cache$st st(
        .d(st$d),
        .q(st$q),
        .clock(st$clock)
    );
    texture_path$unit$cache$clr clr(
        .d(clr$d),
        .q(clr$q),
        .clock(clr$clock)
    );
    texture_path$unit$cache$flush_pend flush_pend(
        .d(flush_pend$d),
        .q(flush_pend$q),
        .clock(flush_pend$clock)
    );
    texture_path$unit$cache$s1_valid s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    texture_path$unit$cache$s1_fresh s1_fresh(
        .d(s1_fresh$d),
        .q(s1_fresh$q),
        .clock(s1_fresh$clock)
    );
    texture_path$unit$cache$s1_en s1_en(
        .d(s1_en$d),
        .q(s1_en$q),
        .clock(s1_en$clock)
    );
    texture_path$unit$cache$s1_addr$0 s1_addr$0(
        .d(s1_addr$0$d),
        .q(s1_addr$0$q),
        .clock(s1_addr$0$clock)
    );
    texture_path$unit$cache$s1_addr$1 s1_addr$1(
        .d(s1_addr$1$d),
        .q(s1_addr$1$q),
        .clock(s1_addr$1$clock)
    );
    texture_path$unit$cache$s1_addr$2 s1_addr$2(
        .d(s1_addr$2$d),
        .q(s1_addr$2$q),
        .clock(s1_addr$2$clock)
    );
    texture_path$unit$cache$s1_addr$3 s1_addr$3(
        .d(s1_addr$3$d),
        .q(s1_addr$3$q),
        .clock(s1_addr$3$clock)
    );
    texture_path$unit$cache$s1_side s1_side(
        .d(s1_side$d),
        .q(s1_side$q),
        .clock(s1_side$clock)
    );
    texture_path$unit$cache$o_valid o_valid(
        .d(o_valid$d),
        .q(o_valid$q),
        .clock(o_valid$clock)
    );
    texture_path$unit$cache$o_data$0 o_data$0(
        .d(o_data$0$d),
        .q(o_data$0$q),
        .clock(o_data$0$clock)
    );
    texture_path$unit$cache$o_data$1 o_data$1(
        .d(o_data$1$d),
        .q(o_data$1$q),
        .clock(o_data$1$clock)
    );
    texture_path$unit$cache$o_data$2 o_data$2(
        .d(o_data$2$d),
        .q(o_data$2$q),
        .clock(o_data$2$clock)
    );
    texture_path$unit$cache$o_data$3 o_data$3(
        .d(o_data$3$d),
        .q(o_data$3$q),
        .clock(o_data$3$clock)
    );
    texture_path$unit$cache$o_side o_side(
        .d(o_side$d),
        .q(o_side$q),
        .clock(o_side$clock)
    );
    texture_path$unit$cache$iss_mask iss_mask(
        .d(iss_mask$d),
        .q(iss_mask$q),
        .clock(iss_mask$clock)
    );
    texture_path$unit$cache$iss_word iss_word(
        .d(iss_word$d),
        .q(iss_word$q),
        .clock(iss_word$clock)
    );
    texture_path$unit$cache$rcv_mask rcv_mask(
        .d(rcv_mask$d),
        .q(rcv_mask$q),
        .clock(rcv_mask$clock)
    );
    texture_path$unit$cache$rcv_word rcv_word(
        .d(rcv_word$d),
        .q(rcv_word$q),
        .clock(rcv_word$clock)
    );
    texture_path$unit$cache$hits_r hits_r(
        .d(hits_r$d),
        .q(hits_r$q),
        .clock(hits_r$clock)
    );
    texture_path$unit$cache$misses_r misses_r(
        .d(misses_r$d),
        .q(misses_r$q),
        .clock(misses_r$clock)
    );
    texture_path$unit$cache$fills_r fills_r(
        .d(fills_r$d),
        .q(fills_r$q),
        .clock(fills_r$clock)
    );
    
    // Update code
    always @(*) begin
        st$clock = clock;
        clr$clock = clock;
        flush_pend$clock = clock;
        s1_valid$clock = clock;
        s1_fresh$clock = clock;
        s1_en$clock = clock;
        s1_side$clock = clock;
        o_valid$clock = clock;
        o_side$clock = clock;
        iss_mask$clock = clock;
        iss_word$clock = clock;
        rcv_mask$clock = clock;
        rcv_word$clock = clock;
        hits_r$clock = clock;
        misses_r$clock = clock;
        fills_r$clock = clock;
        st$d = st$q;
        clr$d = clr$q;
        flush_pend$d = flush_pend$q;
        s1_valid$d = s1_valid$q;
        s1_fresh$d = s1_fresh$q;
        s1_en$d = s1_en$q;
        s1_side$d = s1_side$q;
        o_valid$d = o_valid$q;
        o_side$d = o_side$q;
        iss_mask$d = iss_mask$q;
        iss_word$d = iss_word$q;
        rcv_mask$d = rcv_mask$q;
        rcv_word$d = rcv_word$q;
        hits_r$d = hits_r$q;
        misses_r$d = misses_r$q;
        fills_r$d = fills_r$q;
        s1_addr$0$clock = clock;
        s1_addr$0$d = s1_addr$0$q;
        o_data$0$clock = clock;
        o_data$0$d = o_data$0$q;
        banks$0$clock = clock;
        banks$0$addr = s1_addr$0$q;
        s1_addr$1$clock = clock;
        s1_addr$1$d = s1_addr$1$q;
        o_data$1$clock = clock;
        o_data$1$d = o_data$1$q;
        banks$1$clock = clock;
        banks$1$addr = s1_addr$1$q;
        s1_addr$2$clock = clock;
        s1_addr$2$d = s1_addr$2$q;
        o_data$2$clock = clock;
        o_data$2$d = o_data$2$q;
        banks$2$clock = clock;
        banks$2$addr = s1_addr$2$q;
        s1_addr$3$clock = clock;
        s1_addr$3$d = s1_addr$3$q;
        o_data$3$clock = clock;
        o_data$3$d = o_data$3$q;
        banks$3$clock = clock;
        banks$3$addr = s1_addr$3$q;
        run = st$q == 32'h1;
        all_hit = 1'b1;
        miss_mask = 32'h0;
        n_hit = 32'h0;
        n_miss = 32'h0;
        if (s1_en$q[0]) begin
            if (banks$0$hit) begin
                n_hit = n_hit + 32'h1;
            end
            else begin
                n_miss = n_miss + 32'h1;
                all_hit = 1'b0;
                miss_mask = (miss_mask & ~(1 << (0)) | ((1'b1) << (0)));
            end
        end
        if (s1_en$q[1]) begin
            if (banks$1$hit) begin
                n_hit = n_hit + 32'h1;
            end
            else begin
                n_miss = n_miss + 32'h1;
                all_hit = 1'b0;
                miss_mask = (miss_mask & ~(1 << (1)) | ((1'b1) << (1)));
            end
        end
        if (s1_en$q[2]) begin
            if (banks$2$hit) begin
                n_hit = n_hit + 32'h1;
            end
            else begin
                n_miss = n_miss + 32'h1;
                all_hit = 1'b0;
                miss_mask = (miss_mask & ~(1 << (2)) | ((1'b1) << (2)));
            end
        end
        if (s1_en$q[3]) begin
            if (banks$3$hit) begin
                n_hit = n_hit + 32'h1;
            end
            else begin
                n_miss = n_miss + 32'h1;
                all_hit = 1'b0;
                miss_mask = (miss_mask & ~(1 << (3)) | ((1'b1) << (3)));
            end
        end
        o_free = ~o_valid$q | out_ready;
        s1_go = run & s1_valid$q & all_hit & o_free;
        pending = flush_pend$q | inp_flush;
        inp_ready = run & ~pending & (~s1_valid$q | s1_go);
        take = inp_valid & inp_ready;
        banks$0$rd_addr = s1_addr$0$q[(32'h0)+:(8)];
        banks$1$rd_addr = s1_addr$1$q[(32'h0)+:(8)];
        banks$2$rd_addr = s1_addr$2$q[(32'h0)+:(8)];
        banks$3$rd_addr = s1_addr$3$q[(32'h0)+:(8)];
        s1_fresh$d = take;
        if (take) begin
            banks$0$rd_addr = inp_addr0[(32'h0)+:(8)];
            banks$1$rd_addr = inp_addr1[(32'h0)+:(8)];
            banks$2$rd_addr = inp_addr2[(32'h0)+:(8)];
            banks$3$rd_addr = inp_addr3[(32'h0)+:(8)];
            s1_valid$d = 1'b1;
            s1_en$d = inp_en;
            s1_addr$0$d = inp_addr0;
            s1_addr$1$d = inp_addr1;
            s1_addr$2$d = inp_addr2;
            s1_addr$3$d = inp_addr3;
            s1_side$d = inp_side;
        end
        else if (s1_go) begin
            s1_valid$d = 1'b0;
        end
        out_valid = o_valid$q;
        out_data0 = o_data$0$q;
        out_data1 = o_data$1$q;
        out_data2 = o_data$2$q;
        out_data3 = o_data$3$q;
        out_side = o_side$q;
        if (s1_go) begin
            o_valid$d = 1'b1;
            o_side$d = s1_side$q;
            o_data$0$d = 32'h0;
            if (s1_en$q[0]) begin
                o_data$0$d = banks$0$data;
            end
            o_data$1$d = 32'h0;
            if (s1_en$q[1]) begin
                o_data$1$d = banks$1$data;
            end
            o_data$2$d = 32'h0;
            if (s1_en$q[2]) begin
                o_data$2$d = banks$2$data;
            end
            o_data$3$d = 32'h0;
            if (s1_en$q[3]) begin
                o_data$3$d = banks$3$data;
            end
        end
        else if (out_ready) begin
            o_valid$d = 1'b0;
        end
        counters$hits = hits_r$q;
        counters$misses = misses_r$q;
        counters$fills = fills_r$q;
        if (run & s1_valid$q & s1_fresh$q) begin
            hits_r$d = hits_r$q + n_hit;
            misses_r$d = misses_r$q + n_miss;
        end
        flush_pend$d = pending;
        banks$0$clear = st$q == 32'h0;
        banks$0$clear_set = clr$q;
        banks$1$clear = st$q == 32'h0;
        banks$1$clear_set = clr$q;
        banks$2$clear = st$q == 32'h0;
        banks$2$clear_set = clr$q;
        banks$3$clear = st$q == 32'h0;
        banks$3$clear_set = clr$q;
        if (st$q == 32'h0) begin
            clr$d = clr$q + 32'h1;
            if (&clr$q) begin
                st$d = 32'h1;
            end
        end
        if (run) begin
            if (s1_valid$q & ~all_hit) begin
                st$d = 32'h2;
                iss_mask$d = miss_mask;
                rcv_mask$d = miss_mask;
                iss_word$d = 32'h0;
                rcv_word$d = 32'h0;
            end
            else if (pending & (~s1_valid$q | s1_go)) begin
                st$d = 32'h0;
                clr$d = 32'h0;
                flush_pend$d = 1'b0;
            end
        end
        if (st$q == 32'h3) begin
            st$d = 32'h1;
        end
        iss_lane = 32'h3;
        if (iss_mask$q[32'h2]) begin
            iss_lane = 32'h2;
        end
        if (iss_mask$q[32'h1]) begin
            iss_lane = 32'h1;
        end
        if (iss_mask$q[32'h0]) begin
            iss_lane = 32'h0;
        end
        iss_addr = s1_addr$0$q;
        if (iss_lane == 1) begin
            iss_addr = s1_addr$1$q;
        end
        if (iss_lane == 2) begin
            iss_addr = s1_addr$2$q;
        end
        if (iss_lane == 3) begin
            iss_addr = s1_addr$3$q;
        end
        mem$valid = (st$q == 32'h2) & |iss_mask$q;
        mem$addr = (iss_addr & line_base) | ((iss_word$q) & 26'h3ffffff);
        if (mem$valid & mem$ack) begin
            iss_word$d = iss_word$q + 32'h1;
            if (iss_word$q == word_last) begin
                iss_word$d = 32'h0;
                iss_mask$d = iss_mask$q & (iss_mask$q - 32'h1);
            end
        end
        rcv_lane = 32'h3;
        if (rcv_mask$q[32'h2]) begin
            rcv_lane = 32'h2;
        end
        if (rcv_mask$q[32'h1]) begin
            rcv_lane = 32'h1;
        end
        if (rcv_mask$q[32'h0]) begin
            rcv_lane = 32'h0;
        end
        rcv = (st$q == 32'h2) & |rcv_mask$q & mem$rvalid;
        rcv_last = rcv_word$q == word_last;
        rcv_rest = rcv_mask$q & (rcv_mask$q - 32'h1);
        banks$0$fill = 1'b0;
        if (rcv & (rcv_lane == 0)) begin
            banks$0$fill = 1'b1;
        end
        banks$0$word = rcv_word$q;
        banks$0$wdata = mem$rdata;
        banks$0$last = rcv_last;
        banks$1$fill = 1'b0;
        if (rcv & (rcv_lane == 1)) begin
            banks$1$fill = 1'b1;
        end
        banks$1$word = rcv_word$q;
        banks$1$wdata = mem$rdata;
        banks$1$last = rcv_last;
        banks$2$fill = 1'b0;
        if (rcv & (rcv_lane == 2)) begin
            banks$2$fill = 1'b1;
        end
        banks$2$word = rcv_word$q;
        banks$2$wdata = mem$rdata;
        banks$2$last = rcv_last;
        banks$3$fill = 1'b0;
        if (rcv & (rcv_lane == 3)) begin
            banks$3$fill = 1'b1;
        end
        banks$3$word = rcv_word$q;
        banks$3$wdata = mem$rdata;
        banks$3$last = rcv_last;
        if (rcv) begin
            rcv_word$d = rcv_word$q + 32'h1;
            if (rcv_last) begin
                rcv_word$d = 32'h0;
                rcv_mask$d = rcv_rest;
                fills_r$d = fills_r$q + 32'h1;
                if (~|rcv_rest) begin
                    st$d = 32'h3;
                end
            end
        end
    end
    
endmodule // texture_path$unit$cache


module texture_path$unit$cache$banks$0(clock,rd_addr,addr,fill,word,wdata,last,clear,clear_set,hit,data);
    
    // Module arguments
    input wire  clock;
    input wire  [7:0] rd_addr;
    input wire  [25:0] addr;
    input wire  fill;
    input wire  [7:0] word;
    input wire  [31:0] wdata;
    input wire  last;
    input wire  clear;
    input wire  [5:0] clear_set;
    output reg  hit;
    output reg  [31:0] data;
    
    // Constant declarations
    localparam  set_at = 8'h2;
    localparam  tag_at = 8'h8;
    localparam  word_mask = 8'h3;
    localparam  way_mask = 2'b1;
    localparam  valid_bit = 19'b1;
    
    // Stub signals
    reg  [5:0] tags$0$read_address;
    reg  tags$0$read_clock;
    wire  [18:0] tags$0$read_data;
    reg  [5:0] tags$0$write_address;
    reg  tags$0$write_clock;
    reg  [18:0] tags$0$write_data;
    reg  tags$0$write_enable;
    reg  [5:0] tags$1$read_address;
    reg  tags$1$read_clock;
    wire  [18:0] tags$1$read_data;
    reg  [5:0] tags$1$write_address;
    reg  tags$1$write_clock;
    reg  [18:0] tags$1$write_data;
    reg  tags$1$write_enable;
    reg  [7:0] words$0$read_address;
    reg  words$0$read_clock;
    wire  [31:0] words$0$read_data;
    reg  [7:0] words$0$write_address;
    reg  words$0$write_clock;
    reg  [31:0] words$0$write_data;
    reg  words$0$write_enable;
    reg  [7:0] words$1$read_address;
    reg  words$1$read_clock;
    wire  [31:0] words$1$read_data;
    reg  [7:0] words$1$write_address;
    reg  words$1$write_clock;
    reg  [31:0] words$1$write_data;
    reg  words$1$write_enable;
    reg  [5:0] victim$read_address;
    reg  victim$read_clock;
    wire  [1:0] victim$read_data;
    reg  [5:0] victim$write_address;
    reg  victim$write_clock;
    reg  [1:0] victim$write_data;
    reg  victim$write_enable;
    
    // Local signals
    reg  [5:0] set;
    reg  [17:0] tag;
    reg  [1:0] way;
    reg  [18:0] tag_word;
    
    // Sub module instances
    texture_path$unit$cache$banks$0$tags$0 tags$0(
        .read_address(tags$0$read_address),
        .read_clock(tags$0$read_clock),
        .read_data(tags$0$read_data),
        .write_address(tags$0$write_address),
        .write_clock(tags$0$write_clock),
        .write_data(tags$0$write_data),
        .write_enable(tags$0$write_enable)
    );
    texture_path$unit$cache$banks$0$tags$1 tags$1(
        .read_address(tags$1$read_address),
        .read_clock(tags$1$read_clock),
        .read_data(tags$1$read_data),
        .write_address(tags$1$write_address),
        .write_clock(tags$1$write_clock),
        .write_data(tags$1$write_data),
        .write_enable(tags$1$write_enable)
    );
    texture_path$unit$cache$banks$0$words$0 words$0(
        .read_address(words$0$read_address),
        .read_clock(words$0$read_clock),
        .read_data(words$0$read_data),
        .write_address(words$0$write_address),
        .write_clock(words$0$write_clock),
        .write_data(words$0$write_data),
        .write_enable(words$0$write_enable)
    );
    texture_path$unit$cache$banks$0$words$1 words$1(
        .read_address(words$1$read_address),
        .read_clock(words$1$read_clock),
        .read_data(words$1$read_data),
        .write_address(words$1$write_address),
        .write_clock(words$1$write_clock),
        .write_data(words$1$write_data),
        .write_enable(words$1$write_enable)
    );
    texture_path$unit$cache$banks$0$victim victim(
        .read_address(victim$read_address),
        .read_clock(victim$read_clock),
        .read_data(victim$read_data),
        .write_address(victim$write_address),
        .write_clock(victim$write_clock),
        .write_data(victim$write_data),
        .write_enable(victim$write_enable)
    );
    
    // Update code
    always @(*) begin
        victim$read_clock = clock;
        victim$write_clock = clock;
        victim$read_address = rd_addr[(set_at)+:(6)];
        tags$0$read_clock = clock;
        tags$0$write_clock = clock;
        words$0$read_clock = clock;
        words$0$write_clock = clock;
        tags$0$read_address = rd_addr[(set_at)+:(6)];
        words$0$read_address = rd_addr;
        tags$1$read_clock = clock;
        tags$1$write_clock = clock;
        words$1$read_clock = clock;
        words$1$write_clock = clock;
        tags$1$read_address = rd_addr[(set_at)+:(6)];
        words$1$read_address = rd_addr;
        set = addr[(set_at)+:(6)];
        tag = addr[(tag_at)+:(18)];
        hit = 1'b0;
        data = 32'h0;
        if (tags$0$read_data[32'h0] & (tags$0$read_data[(32'h1)+:(18)] == tag)) begin
            hit = 1'b1;
            data = words$0$read_data;
        end
        if (tags$1$read_data[32'h0] & (tags$1$read_data[(32'h1)+:(18)] == tag)) begin
            hit = 1'b1;
            data = words$1$read_data;
        end
        way = victim$read_data;
        tag_word = (((tag) & 19'h7ffff) << 32'h1) | valid_bit;
        victim$write_enable = clear | (fill & last);
        victim$write_address = set;
        victim$write_data = (way + 32'h1) & way_mask;
        if (clear) begin
            victim$write_address = clear_set;
            victim$write_data = 32'h0;
        end
        words$0$write_enable = 1'b0;
        tags$0$write_enable = clear;
        if (fill & (way == 0)) begin
            words$0$write_enable = 1'b1;
            tags$0$write_enable = last;
        end
        words$0$write_address = (addr[(32'h0)+:(8)] & ~word_mask) | word;
        words$0$write_data = wdata;
        tags$0$write_address = set;
        tags$0$write_data = tag_word;
        if (clear) begin
            tags$0$write_address = clear_set;
            tags$0$write_data = 32'h0;
        end
        words$1$write_enable = 1'b0;
        tags$1$write_enable = clear;
        if (fill & (way == 1)) begin
            words$1$write_enable = 1'b1;
            tags$1$write_enable = last;
        end
        words$1$write_address = (addr[(32'h0)+:(8)] & ~word_mask) | word;
        words$1$write_data = wdata;
        tags$1$write_address = set;
        tags$1$write_data = tag_word;
        if (clear) begin
            tags$1$write_address = clear_set;
            tags$1$write_data = 32'h0;
        end
    end
    
endmodule // texture_path$unit$cache$banks$0


module texture_path$unit$cache$banks$0$tags$0(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [5:0] read_address;
    input wire  read_clock;
    output reg  [18:0] read_data;
    input wire  [5:0] write_address;
    input wire  write_clock;
    input wire  [18:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[18:0] mem[63:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // texture_path$unit$cache$banks$0$tags$0


module texture_path$unit$cache$banks$0$tags$1(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [5:0] read_address;
    input wire  read_clock;
    output reg  [18:0] read_data;
    input wire  [5:0] write_address;
    input wire  write_clock;
    input wire  [18:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[18:0] mem[63:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // texture_path$unit$cache$banks$0$tags$1


module texture_path$unit$cache$banks$0$victim(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [5:0] read_address;
    input wire  read_clock;
    output reg  [1:0] read_data;
    input wire  [5:0] write_address;
    input wire  write_clock;
    input wire  [1:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[1:0] mem[63:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // texture_path$unit$cache$banks$0$victim


module texture_path$unit$cache$banks$0$words$0(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [7:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [7:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[31:0] mem[255:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // texture_path$unit$cache$banks$0$words$0


module texture_path$unit$cache$banks$0$words$1(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [7:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [7:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[31:0] mem[255:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // texture_path$unit$cache$banks$0$words$1


module texture_path$unit$cache$banks$1(clock,rd_addr,addr,fill,word,wdata,last,clear,clear_set,hit,data);
    
    // Module arguments
    input wire  clock;
    input wire  [7:0] rd_addr;
    input wire  [25:0] addr;
    input wire  fill;
    input wire  [7:0] word;
    input wire  [31:0] wdata;
    input wire  last;
    input wire  clear;
    input wire  [5:0] clear_set;
    output reg  hit;
    output reg  [31:0] data;
    
    // Constant declarations
    localparam  set_at = 8'h2;
    localparam  tag_at = 8'h8;
    localparam  word_mask = 8'h3;
    localparam  way_mask = 2'b1;
    localparam  valid_bit = 19'b1;
    
    // Stub signals
    reg  [5:0] tags$0$read_address;
    reg  tags$0$read_clock;
    wire  [18:0] tags$0$read_data;
    reg  [5:0] tags$0$write_address;
    reg  tags$0$write_clock;
    reg  [18:0] tags$0$write_data;
    reg  tags$0$write_enable;
    reg  [5:0] tags$1$read_address;
    reg  tags$1$read_clock;
    wire  [18:0] tags$1$read_data;
    reg  [5:0] tags$1$write_address;
    reg  tags$1$write_clock;
    reg  [18:0] tags$1$write_data;
    reg  tags$1$write_enable;
    reg  [7:0] words$0$read_address;
    reg  words$0$read_clock;
    wire  [31:0] words$0$read_data;
    reg  [7:0] words$0$write_address;
    reg  words$0$write_clock;
    reg  [31:0] words$0$write_data;
    reg  words$0$write_enable;
    reg  [7:0] words$1$read_address;
    reg  words$1$read_clock;
    wire  [31:0] words$1$read_data;
    reg  [7:0] words$1$write_address;
    reg  words$1$write_clock;
    reg  [31:0] words$1$write_data;
    reg  words$1$write_enable;
    reg  [5:0] victim$read_address;
    reg  victim$read_clock;
    wire  [1:0] victim$read_data;
    reg  [5:0] victim$write_address;
    reg  victim$write_clock;
    reg  [1:0] victim$write_data;
    reg  victim$write_enable;
    
    // Local signals
    reg  [5:0] set;
    reg  [17:0] tag;
    reg  [1:0] way;
    reg  [18:0] tag_word;
    
    // Sub module instances
    texture_path$unit$cache$banks$1$tags$0 tags$0(
        .read_address(tags$0$read_address),
        .read_clock(tags$0$read_clock),
        .read_data(tags$0$read_data),
        .write_address(tags$0$write_address),
        .write_clock(tags$0$write_clock),
        .write_data(tags$0$write_data),
        .write_enable(tags$0$write_enable)
    );
    texture_path$unit$cache$banks$1$tags$1 tags$1(
        .read_address(tags$1$read_address),
        .read_clock(tags$1$read_clock),
        .read_data(tags$1$read_data),
        .write_address(tags$1$write_address),
        .write_clock(tags$1$write_clock),
        .write_data(tags$1$write_data),
        .write_enable(tags$1$write_enable)
    );
    texture_path$unit$cache$banks$1$words$0 words$0(
        .read_address(words$0$read_address),
        .read_clock(words$0$read_clock),
        .read_data(words$0$read_data),
        .write_address(words$0$write_address),
        .write_clock(words$0$write_clock),
        .write_data(words$0$write_data),
        .write_enable(words$0$write_enable)
    );
    texture_path$unit$cache$banks$1$words$1 words$1(
        .read_address(words$1$read_address),
        .read_clock(words$1$read_clock),
        .read_data(words$1$read_data),
        .write_address(words$1$write_address),
        .write_clock(words$1$write_clock),
        .write_data(words$1$write_data),
        .write_enable(words$1$write_enable)
    );
    texture_path$unit$cache$banks$1$victim victim(
        .read_address(victim$read_address),
        .read_clock(victim$read_clock),
        .read_data(victim$read_data),
        .write_address(victim$write_address),
        .write_clock(victim$write_clock),
        .write_data(victim$write_data),
        .write_enable(victim$write_enable)
    );
    
    // Update code
    always @(*) begin
        victim$read_clock = clock;
        victim$write_clock = clock;
        victim$read_address = rd_addr[(set_at)+:(6)];
        tags$0$read_clock = clock;
        tags$0$write_clock = clock;
        words$0$read_clock = clock;
        words$0$write_clock = clock;
        tags$0$read_address = rd_addr[(set_at)+:(6)];
        words$0$read_address = rd_addr;
        tags$1$read_clock = clock;
        tags$1$write_clock = clock;
        words$1$read_clock = clock;
        words$1$write_clock = clock;
        tags$1$read_address = rd_addr[(set_at)+:(6)];
        words$1$read_address = rd_addr;
        set = addr[(set_at)+:(6)];
        tag = addr[(tag_at)+:(18)];
        hit = 1'b0;
        data = 32'h0;
        if (tags$0$read_data[32'h0] & (tags$0$read_data[(32'h1)+:(18)] == tag)) begin
            hit = 1'b1;
            data = words$0$read_data;
        end
        if (tags$1$read_data[32'h0] & (tags$1$read_data[(32'h1)+:(18)] == tag)) begin
            hit = 1'b1;
            data = words$1$read_data;
        end
        way = victim$read_data;
        tag_word = (((tag) & 19'h7ffff) << 32'h1) | valid_bit;
        victim$write_enable = clear | (fill & last);
        victim$write_address = set;
        victim$write_data = (way + 32'h1) & way_mask;
        if (clear) begin
            victim$write_address = clear_set;
            victim$write_data = 32'h0;
        end
        words$0$write_enable = 1'b0;
        tags$0$write_enable = clear;
        if (fill & (way == 0)) begin
            words$0$write_enable = 1'b1;
            tags$0$write_enable = last;
        end
        words$0$write_address = (addr[(32'h0)+:(8)] & ~word_mask) | word;
        words$0$write_data = wdata;
        tags$0$write_address = set;
        tags$0$write_data = tag_word;
        if (clear) begin
            tags$0$write_address = clear_set;
            tags$0$write_data = 32'h0;
        end
        words$1$write_enable = 1'b0;
        tags$1$write_enable = clear;
        if (fill & (way == 1)) begin
            words$1$write_enable = 1'b1;
            tags$1$write_enable = last;
        end
        words$1$write_address = (addr[(32'h0)+:(8)] & ~word_mask) | word;
        words$1$write_data = wdata;
        tags$1$write_address = set;
        tags$1$write_data = tag_word;
        if (clear) begin
            tags$1$write_address = clear_set;
            tags$1$write_data = 32'h0;
        end
    end
    
endmodule // texture_path$unit$cache$banks$1


module texture_path$unit$cache$banks$1$tags$0(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [5:0] read_address;
    input wire  read_clock;
    output reg  [18:0] read_data;
    input wire  [5:0] write_address;
    input wire  write_clock;
    input wire  [18:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[18:0] mem[63:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // texture_path$unit$cache$banks$1$tags$0


module texture_path$unit$cache$banks$1$tags$1(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [5:0] read_address;
    input wire  read_clock;
    output reg  [18:0] read_data;
    input wire  [5:0] write_address;
    input wire  write_clock;
    input wire  [18:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[18:0] mem[63:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // texture_path$unit$cache$banks$1$tags$1


module texture_path$unit$cache$banks$1$victim(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [5:0] read_address;
    input wire  read_clock;
    output reg  [1:0] read_data;
    input wire  [5:0] write_address;
    input wire  write_clock;
    input wire  [1:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[1:0] mem[63:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // texture_path$unit$cache$banks$1$victim


module texture_path$unit$cache$banks$1$words$0(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [7:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [7:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[31:0] mem[255:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // texture_path$unit$cache$banks$1$words$0


module texture_path$unit$cache$banks$1$words$1(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [7:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [7:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[31:0] mem[255:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // texture_path$unit$cache$banks$1$words$1


module texture_path$unit$cache$banks$2(clock,rd_addr,addr,fill,word,wdata,last,clear,clear_set,hit,data);
    
    // Module arguments
    input wire  clock;
    input wire  [7:0] rd_addr;
    input wire  [25:0] addr;
    input wire  fill;
    input wire  [7:0] word;
    input wire  [31:0] wdata;
    input wire  last;
    input wire  clear;
    input wire  [5:0] clear_set;
    output reg  hit;
    output reg  [31:0] data;
    
    // Constant declarations
    localparam  set_at = 8'h2;
    localparam  tag_at = 8'h8;
    localparam  word_mask = 8'h3;
    localparam  way_mask = 2'b1;
    localparam  valid_bit = 19'b1;
    
    // Stub signals
    reg  [5:0] tags$0$read_address;
    reg  tags$0$read_clock;
    wire  [18:0] tags$0$read_data;
    reg  [5:0] tags$0$write_address;
    reg  tags$0$write_clock;
    reg  [18:0] tags$0$write_data;
    reg  tags$0$write_enable;
    reg  [5:0] tags$1$read_address;
    reg  tags$1$read_clock;
    wire  [18:0] tags$1$read_data;
    reg  [5:0] tags$1$write_address;
    reg  tags$1$write_clock;
    reg  [18:0] tags$1$write_data;
    reg  tags$1$write_enable;
    reg  [7:0] words$0$read_address;
    reg  words$0$read_clock;
    wire  [31:0] words$0$read_data;
    reg  [7:0] words$0$write_address;
    reg  words$0$write_clock;
    reg  [31:0] words$0$write_data;
    reg  words$0$write_enable;
    reg  [7:0] words$1$read_address;
    reg  words$1$read_clock;
    wire  [31:0] words$1$read_data;
    reg  [7:0] words$1$write_address;
    reg  words$1$write_clock;
    reg  [31:0] words$1$write_data;
    reg  words$1$write_enable;
    reg  [5:0] victim$read_address;
    reg  victim$read_clock;
    wire  [1:0] victim$read_data;
    reg  [5:0] victim$write_address;
    reg  victim$write_clock;
    reg  [1:0] victim$write_data;
    reg  victim$write_enable;
    
    // Local signals
    reg  [5:0] set;
    reg  [17:0] tag;
    reg  [1:0] way;
    reg  [18:0] tag_word;
    
    // Sub module instances
    texture_path$unit$cache$banks$2$tags$0 tags$0(
        .read_address(tags$0$read_address),
        .read_clock(tags$0$read_clock),
        .read_data(tags$0$read_data),
        .write_address(tags$0$write_address),
        .write_clock(tags$0$write_clock),
        .write_data(tags$0$write_data),
        .write_enable(tags$0$write_enable)
    );
    texture_path$unit$cache$banks$2$tags$1 tags$1(
        .read_address(tags$1$read_address),
        .read_clock(tags$1$read_clock),
        .read_data(tags$1$read_data),
        .write_address(tags$1$write_address),
        .write_clock(tags$1$write_clock),
        .write_data(tags$1$write_data),
        .write_enable(tags$1$write_enable)
    );
    texture_path$unit$cache$banks$2$words$0 words$0(
        .read_address(words$0$read_address),
        .read_clock(words$0$read_clock),
        .read_data(words$0$read_data),
        .write_address(words$0$write_address),
        .write_clock(words$0$write_clock),
        .write_data(words$0$write_data),
        .write_enable(words$0$write_enable)
    );
    texture_path$unit$cache$banks$2$words$1 words$1(
        .read_address(words$1$read_address),
        .read_clock(words$1$read_clock),
        .read_data(words$1$read_data),
        .write_address(words$1$write_address),
        .write_clock(words$1$write_clock),
        .write_data(words$1$write_data),
        .write_enable(words$1$write_enable)
    );
    texture_path$unit$cache$banks$2$victim victim(
        .read_address(victim$read_address),
        .read_clock(victim$read_clock),
        .read_data(victim$read_data),
        .write_address(victim$write_address),
        .write_clock(victim$write_clock),
        .write_data(victim$write_data),
        .write_enable(victim$write_enable)
    );
    
    // Update code
    always @(*) begin
        victim$read_clock = clock;
        victim$write_clock = clock;
        victim$read_address = rd_addr[(set_at)+:(6)];
        tags$0$read_clock = clock;
        tags$0$write_clock = clock;
        words$0$read_clock = clock;
        words$0$write_clock = clock;
        tags$0$read_address = rd_addr[(set_at)+:(6)];
        words$0$read_address = rd_addr;
        tags$1$read_clock = clock;
        tags$1$write_clock = clock;
        words$1$read_clock = clock;
        words$1$write_clock = clock;
        tags$1$read_address = rd_addr[(set_at)+:(6)];
        words$1$read_address = rd_addr;
        set = addr[(set_at)+:(6)];
        tag = addr[(tag_at)+:(18)];
        hit = 1'b0;
        data = 32'h0;
        if (tags$0$read_data[32'h0] & (tags$0$read_data[(32'h1)+:(18)] == tag)) begin
            hit = 1'b1;
            data = words$0$read_data;
        end
        if (tags$1$read_data[32'h0] & (tags$1$read_data[(32'h1)+:(18)] == tag)) begin
            hit = 1'b1;
            data = words$1$read_data;
        end
        way = victim$read_data;
        tag_word = (((tag) & 19'h7ffff) << 32'h1) | valid_bit;
        victim$write_enable = clear | (fill & last);
        victim$write_address = set;
        victim$write_data = (way + 32'h1) & way_mask;
        if (clear) begin
            victim$write_address = clear_set;
            victim$write_data = 32'h0;
        end
        words$0$write_enable = 1'b0;
        tags$0$write_enable = clear;
        if (fill & (way == 0)) begin
            words$0$write_enable = 1'b1;
            tags$0$write_enable = last;
        end
        words$0$write_address = (addr[(32'h0)+:(8)] & ~word_mask) | word;
        words$0$write_data = wdata;
        tags$0$write_address = set;
        tags$0$write_data = tag_word;
        if (clear) begin
            tags$0$write_address = clear_set;
            tags$0$write_data = 32'h0;
        end
        words$1$write_enable = 1'b0;
        tags$1$write_enable = clear;
        if (fill & (way == 1)) begin
            words$1$write_enable = 1'b1;
            tags$1$write_enable = last;
        end
        words$1$write_address = (addr[(32'h0)+:(8)] & ~word_mask) | word;
        words$1$write_data = wdata;
        tags$1$write_address = set;
        tags$1$write_data = tag_word;
        if (clear) begin
            tags$1$write_address = clear_set;
            tags$1$write_data = 32'h0;
        end
    end
    
endmodule // texture_path$unit$cache$banks$2


module texture_path$unit$cache$banks$2$tags$0(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [5:0] read_address;
    input wire  read_clock;
    output reg  [18:0] read_data;
    input wire  [5:0] write_address;
    input wire  write_clock;
    input wire  [18:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[18:0] mem[63:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // texture_path$unit$cache$banks$2$tags$0


module texture_path$unit$cache$banks$2$tags$1(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [5:0] read_address;
    input wire  read_clock;
    output reg  [18:0] read_data;
    input wire  [5:0] write_address;
    input wire  write_clock;
    input wire  [18:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[18:0] mem[63:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // texture_path$unit$cache$banks$2$tags$1


module texture_path$unit$cache$banks$2$victim(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [5:0] read_address;
    input wire  read_clock;
    output reg  [1:0] read_data;
    input wire  [5:0] write_address;
    input wire  write_clock;
    input wire  [1:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[1:0] mem[63:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // texture_path$unit$cache$banks$2$victim


module texture_path$unit$cache$banks$2$words$0(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [7:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [7:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[31:0] mem[255:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // texture_path$unit$cache$banks$2$words$0


module texture_path$unit$cache$banks$2$words$1(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [7:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [7:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[31:0] mem[255:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // texture_path$unit$cache$banks$2$words$1


module texture_path$unit$cache$banks$3(clock,rd_addr,addr,fill,word,wdata,last,clear,clear_set,hit,data);
    
    // Module arguments
    input wire  clock;
    input wire  [7:0] rd_addr;
    input wire  [25:0] addr;
    input wire  fill;
    input wire  [7:0] word;
    input wire  [31:0] wdata;
    input wire  last;
    input wire  clear;
    input wire  [5:0] clear_set;
    output reg  hit;
    output reg  [31:0] data;
    
    // Constant declarations
    localparam  set_at = 8'h2;
    localparam  tag_at = 8'h8;
    localparam  word_mask = 8'h3;
    localparam  way_mask = 2'b1;
    localparam  valid_bit = 19'b1;
    
    // Stub signals
    reg  [5:0] tags$0$read_address;
    reg  tags$0$read_clock;
    wire  [18:0] tags$0$read_data;
    reg  [5:0] tags$0$write_address;
    reg  tags$0$write_clock;
    reg  [18:0] tags$0$write_data;
    reg  tags$0$write_enable;
    reg  [5:0] tags$1$read_address;
    reg  tags$1$read_clock;
    wire  [18:0] tags$1$read_data;
    reg  [5:0] tags$1$write_address;
    reg  tags$1$write_clock;
    reg  [18:0] tags$1$write_data;
    reg  tags$1$write_enable;
    reg  [7:0] words$0$read_address;
    reg  words$0$read_clock;
    wire  [31:0] words$0$read_data;
    reg  [7:0] words$0$write_address;
    reg  words$0$write_clock;
    reg  [31:0] words$0$write_data;
    reg  words$0$write_enable;
    reg  [7:0] words$1$read_address;
    reg  words$1$read_clock;
    wire  [31:0] words$1$read_data;
    reg  [7:0] words$1$write_address;
    reg  words$1$write_clock;
    reg  [31:0] words$1$write_data;
    reg  words$1$write_enable;
    reg  [5:0] victim$read_address;
    reg  victim$read_clock;
    wire  [1:0] victim$read_data;
    reg  [5:0] victim$write_address;
    reg  victim$write_clock;
    reg  [1:0] victim$write_data;
    reg  victim$write_enable;
    
    // Local signals
    reg  [5:0] set;
    reg  [17:0] tag;
    reg  [1:0] way;
    reg  [18:0] tag_word;
    
    // Sub module instances
    texture_path$unit$cache$banks$3$tags$0 tags$0(
        .read_address(tags$0$read_address),
        .read_clock(tags$0$read_clock),
        .read_data(tags$0$read_data),
        .write_address(tags$0$write_address),
        .write_clock(tags$0$write_clock),
        .write_data(tags$0$write_data),
        .write_enable(tags$0$write_enable)
    );
    texture_path$unit$cache$banks$3$tags$1 tags$1(
        .read_address(tags$1$read_address),
        .read_clock(tags$1$read_clock),
        .read_data(tags$1$read_data),
        .write_address(tags$1$write_address),
        .write_clock(tags$1$write_clock),
        .write_data(tags$1$write_data),
        .write_enable(tags$1$write_enable)
    );
    texture_path$unit$cache$banks$3$words$0 words$0(
        .read_address(words$0$read_address),
        .read_clock(words$0$read_clock),
        .read_data(words$0$read_data),
        .write_address(words$0$write_address),
        .write_clock(words$0$write_clock),
        .write_data(words$0$write_data),
        .write_enable(words$0$write_enable)
    );
    texture_path$unit$cache$banks$3$words$1 words$1(
        .read_address(words$1$read_address),
        .read_clock(words$1$read_clock),
        .read_data(words$1$read_data),
        .write_address(words$1$write_address),
        .write_clock(words$1$write_clock),
        .write_data(words$1$write_data),
        .write_enable(words$1$write_enable)
    );
    texture_path$unit$cache$banks$3$victim victim(
        .read_address(victim$read_address),
        .read_clock(victim$read_clock),
        .read_data(victim$read_data),
        .write_address(victim$write_address),
        .write_clock(victim$write_clock),
        .write_data(victim$write_data),
        .write_enable(victim$write_enable)
    );
    
    // Update code
    always @(*) begin
        victim$read_clock = clock;
        victim$write_clock = clock;
        victim$read_address = rd_addr[(set_at)+:(6)];
        tags$0$read_clock = clock;
        tags$0$write_clock = clock;
        words$0$read_clock = clock;
        words$0$write_clock = clock;
        tags$0$read_address = rd_addr[(set_at)+:(6)];
        words$0$read_address = rd_addr;
        tags$1$read_clock = clock;
        tags$1$write_clock = clock;
        words$1$read_clock = clock;
        words$1$write_clock = clock;
        tags$1$read_address = rd_addr[(set_at)+:(6)];
        words$1$read_address = rd_addr;
        set = addr[(set_at)+:(6)];
        tag = addr[(tag_at)+:(18)];
        hit = 1'b0;
        data = 32'h0;
        if (tags$0$read_data[32'h0] & (tags$0$read_data[(32'h1)+:(18)] == tag)) begin
            hit = 1'b1;
            data = words$0$read_data;
        end
        if (tags$1$read_data[32'h0] & (tags$1$read_data[(32'h1)+:(18)] == tag)) begin
            hit = 1'b1;
            data = words$1$read_data;
        end
        way = victim$read_data;
        tag_word = (((tag) & 19'h7ffff) << 32'h1) | valid_bit;
        victim$write_enable = clear | (fill & last);
        victim$write_address = set;
        victim$write_data = (way + 32'h1) & way_mask;
        if (clear) begin
            victim$write_address = clear_set;
            victim$write_data = 32'h0;
        end
        words$0$write_enable = 1'b0;
        tags$0$write_enable = clear;
        if (fill & (way == 0)) begin
            words$0$write_enable = 1'b1;
            tags$0$write_enable = last;
        end
        words$0$write_address = (addr[(32'h0)+:(8)] & ~word_mask) | word;
        words$0$write_data = wdata;
        tags$0$write_address = set;
        tags$0$write_data = tag_word;
        if (clear) begin
            tags$0$write_address = clear_set;
            tags$0$write_data = 32'h0;
        end
        words$1$write_enable = 1'b0;
        tags$1$write_enable = clear;
        if (fill & (way == 1)) begin
            words$1$write_enable = 1'b1;
            tags$1$write_enable = last;
        end
        words$1$write_address = (addr[(32'h0)+:(8)] & ~word_mask) | word;
        words$1$write_data = wdata;
        tags$1$write_address = set;
        tags$1$write_data = tag_word;
        if (clear) begin
            tags$1$write_address = clear_set;
            tags$1$write_data = 32'h0;
        end
    end
    
endmodule // texture_path$unit$cache$banks$3


module texture_path$unit$cache$banks$3$tags$0(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [5:0] read_address;
    input wire  read_clock;
    output reg  [18:0] read_data;
    input wire  [5:0] write_address;
    input wire  write_clock;
    input wire  [18:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[18:0] mem[63:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // texture_path$unit$cache$banks$3$tags$0


module texture_path$unit$cache$banks$3$tags$1(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [5:0] read_address;
    input wire  read_clock;
    output reg  [18:0] read_data;
    input wire  [5:0] write_address;
    input wire  write_clock;
    input wire  [18:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[18:0] mem[63:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // texture_path$unit$cache$banks$3$tags$1


module texture_path$unit$cache$banks$3$victim(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [5:0] read_address;
    input wire  read_clock;
    output reg  [1:0] read_data;
    input wire  [5:0] write_address;
    input wire  write_clock;
    input wire  [1:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[1:0] mem[63:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // texture_path$unit$cache$banks$3$victim


module texture_path$unit$cache$banks$3$words$0(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [7:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [7:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[31:0] mem[255:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // texture_path$unit$cache$banks$3$words$0


module texture_path$unit$cache$banks$3$words$1(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [7:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [7:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[31:0] mem[255:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // texture_path$unit$cache$banks$3$words$1


module texture_path$unit$cache$clr(d,q,clock);
    
    // Module arguments
    input wire  [5:0] d;
    output reg  [5:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 6'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$cache$clr


module texture_path$unit$cache$fills_r(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$cache$fills_r


module texture_path$unit$cache$flush_pend(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$cache$flush_pend


module texture_path$unit$cache$hits_r(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$cache$hits_r


module texture_path$unit$cache$iss_mask(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$cache$iss_mask


module texture_path$unit$cache$iss_word(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$cache$iss_word


module texture_path$unit$cache$misses_r(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$cache$misses_r


module texture_path$unit$cache$o_data$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$cache$o_data$0


module texture_path$unit$cache$o_data$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$cache$o_data$1


module texture_path$unit$cache$o_data$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$cache$o_data$2


module texture_path$unit$cache$o_data$3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$cache$o_data$3


module texture_path$unit$cache$o_side(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$cache$o_side


module texture_path$unit$cache$o_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$cache$o_valid


module texture_path$unit$cache$rcv_mask(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$cache$rcv_mask


module texture_path$unit$cache$rcv_word(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$cache$rcv_word


module texture_path$unit$cache$s1_addr$0(d,q,clock);
    
    // Module arguments
    input wire  [25:0] d;
    output reg  [25:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 26'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$cache$s1_addr$0


module texture_path$unit$cache$s1_addr$1(d,q,clock);
    
    // Module arguments
    input wire  [25:0] d;
    output reg  [25:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 26'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$cache$s1_addr$1


module texture_path$unit$cache$s1_addr$2(d,q,clock);
    
    // Module arguments
    input wire  [25:0] d;
    output reg  [25:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 26'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$cache$s1_addr$2


module texture_path$unit$cache$s1_addr$3(d,q,clock);
    
    // Module arguments
    input wire  [25:0] d;
    output reg  [25:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 26'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$cache$s1_addr$3


module texture_path$unit$cache$s1_en(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$cache$s1_en


module texture_path$unit$cache$s1_fresh(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$cache$s1_fresh


module texture_path$unit$cache$s1_side(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$cache$s1_side


module texture_path$unit$cache$s1_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$cache$s1_valid


module texture_path$unit$cache$st(d,q,clock);
    
    // Module arguments
    input wire  [1:0] d;
    output reg  [1:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 2'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$cache$st


module texture_path$unit$cf_ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [5:0] read_address;
    input wire  read_clock;
    output reg  [23:0] read_data;
    input wire  [5:0] write_address;
    input wire  write_clock;
    input wire  [23:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[23:0] mem[63:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // texture_path$unit$cf_ram


module texture_path$unit$coords(clock,en,inp_valid,inp_sq,inp_tq,inp_q,inp_dsq_x,inp_dsq_y,inp_dtq_x,inp_dtq_y,inp_dq_x,inp_dq_y,inp_ws,inp_hs,out_valid,out_s,out_t,out_lambda);
    
    // Module arguments
    input wire  clock;
    input wire  en;
    input wire  inp_valid;
    input wire  [28:0] inp_sq;
    input wire  [28:0] inp_tq;
    input wire  [20:0] inp_q;
    input wire  [32:0] inp_dsq_x;
    input wire  [32:0] inp_dsq_y;
    input wire  [32:0] inp_dtq_x;
    input wire  [32:0] inp_dtq_y;
    input wire  [29:0] inp_dq_x;
    input wire  [29:0] inp_dq_y;
    input wire  [3:0] inp_ws;
    input wire  [3:0] inp_hs;
    output reg  out_valid;
    output reg  [28:0] out_s;
    output reg  [28:0] out_t;
    output reg  [31:0] out_lambda;
    
    // Constant declarations
    localparam  exact = 1'b0;
    localparam  dividend = 47'h200000000000;
    localparam  index$0 = 8'h0;
    localparam  index$1 = 8'h1;
    localparam  index$2 = 8'h2;
    localparam  index$3 = 8'h3;
    localparam  index$4 = 8'h4;
    localparam  index$5 = 8'h5;
    localparam  index$6 = 8'h6;
    localparam  index$7 = 8'h7;
    localparam  index$8 = 8'h8;
    localparam  index$9 = 8'h9;
    localparam  index$10 = 8'ha;
    localparam  index$11 = 8'hb;
    localparam  index$12 = 8'hc;
    localparam  index$13 = 8'hd;
    localparam  index$14 = 8'he;
    localparam  index$15 = 8'hf;
    localparam  index$16 = 8'h10;
    localparam  index$17 = 8'h11;
    localparam  index$18 = 8'h12;
    localparam  index$19 = 8'h13;
    localparam  index$20 = 8'h14;
    localparam  index$21 = 8'h15;
    localparam  index$22 = 8'h16;
    localparam  index$23 = 8'h17;
    localparam  index$24 = 8'h18;
    localparam  index$25 = 8'h19;
    localparam  index$26 = 8'h1a;
    localparam  index$27 = 8'h1b;
    localparam  index$28 = 8'h1c;
    localparam  index$29 = 8'h1d;
    localparam  index$30 = 8'h1e;
    localparam  index$31 = 8'h1f;
    localparam  index$32 = 8'h20;
    localparam  index$33 = 8'h21;
    localparam  index$34 = 8'h22;
    localparam  index$35 = 8'h23;
    localparam  index$36 = 8'h24;
    localparam  index$37 = 8'h25;
    localparam  index$38 = 8'h26;
    localparam  index$39 = 8'h27;
    localparam  index$40 = 8'h28;
    localparam  index$41 = 8'h29;
    localparam  index$42 = 8'h2a;
    localparam  index$43 = 8'h2b;
    localparam  index$44 = 8'h2c;
    localparam  index$45 = 8'h2d;
    localparam  index$46 = 8'h2e;
    localparam  index$47 = 8'h2f;
    localparam  index$48 = 8'h30;
    localparam  index$49 = 8'h31;
    localparam  index$50 = 8'h32;
    localparam  index$51 = 8'h33;
    localparam  index$52 = 8'h34;
    localparam  index$53 = 8'h35;
    localparam  index$54 = 8'h36;
    localparam  index$55 = 8'h37;
    localparam  index$56 = 8'h38;
    localparam  index$57 = 8'h39;
    localparam  index$58 = 8'h3a;
    localparam  index$59 = 8'h3b;
    localparam  index$60 = 8'h3c;
    localparam  index$61 = 8'h3d;
    localparam  index$62 = 8'h3e;
    localparam  index$63 = 8'h3f;
    localparam  index$64 = 8'h40;
    localparam  index$65 = 8'h41;
    localparam  index$66 = 8'h42;
    localparam  index$67 = 8'h43;
    localparam  index$68 = 8'h44;
    localparam  index$69 = 8'h45;
    localparam  index$70 = 8'h46;
    localparam  index$71 = 8'h47;
    localparam  index$72 = 8'h48;
    localparam  index$73 = 8'h49;
    localparam  index$74 = 8'h4a;
    localparam  index$75 = 8'h4b;
    localparam  index$76 = 8'h4c;
    localparam  index$77 = 8'h4d;
    localparam  index$78 = 8'h4e;
    localparam  index$79 = 8'h4f;
    localparam  index$80 = 8'h50;
    localparam  index$81 = 8'h51;
    localparam  index$82 = 8'h52;
    localparam  index$83 = 8'h53;
    localparam  index$84 = 8'h54;
    localparam  index$85 = 8'h55;
    localparam  index$86 = 8'h56;
    localparam  index$87 = 8'h57;
    localparam  index$88 = 8'h58;
    localparam  index$89 = 8'h59;
    localparam  index$90 = 8'h5a;
    localparam  index$91 = 8'h5b;
    localparam  index$92 = 8'h5c;
    localparam  index$93 = 8'h5d;
    localparam  index$94 = 8'h5e;
    localparam  qb_top = 8'h14;
    localparam  recip_1 = 8'h19;
    localparam  st_msb = 8'h1c;
    localparam  ps_msb = 8'h37;
    localparam  g_shift = 8'h18;
    localparam  m_top = 8'h5e;
    localparam  m_index = 8'h54;
    localparam  r_top = 8'h1a;
    localparam  r_index = 8'h10;
    localparam  t_bits = 8'ha;
    localparam  t_less_1 = 8'h9;
    localparam  sum_msb = 8'h17;
    localparam  st_min = 29'h10000000;
    localparam  st_max = 29'hfffffff;
    localparam  ones_ps = 56'hffffffffffffff;
    localparam  ones_sum = 24'hffffff;
    localparam  ext_lambda = 32'hff000000;
    localparam  offset = 24'hff3c00;
    localparam  magnified = 32'hc0000000;
    
    // Stub signals
    reg  recip$clock;
    reg  recip$inp_valid;
    wire  recip$inp_ready;
    reg  recip$hold;
    reg  [46:0] recip$inp_n;
    reg  [20:0] recip$inp_d;
    wire  recip$out_valid;
    reg  recip$out_ready;
    wire  [26:0] recip$out_q;
    wire  [20:0] recip$out_r;
    reg  [28:0] dl_sq$0$d;
    wire  [28:0] dl_sq$0$q;
    reg  dl_sq$0$clock;
    reg  [28:0] dl_sq$1$d;
    wire  [28:0] dl_sq$1$q;
    reg  dl_sq$1$clock;
    reg  [28:0] dl_sq$2$d;
    wire  [28:0] dl_sq$2$q;
    reg  dl_sq$2$clock;
    reg  [28:0] dl_sq$3$d;
    wire  [28:0] dl_sq$3$q;
    reg  dl_sq$3$clock;
    reg  [28:0] dl_sq$4$d;
    wire  [28:0] dl_sq$4$q;
    reg  dl_sq$4$clock;
    reg  [28:0] dl_sq$5$d;
    wire  [28:0] dl_sq$5$q;
    reg  dl_sq$5$clock;
    reg  [28:0] dl_sq$6$d;
    wire  [28:0] dl_sq$6$q;
    reg  dl_sq$6$clock;
    reg  [28:0] dl_sq$7$d;
    wire  [28:0] dl_sq$7$q;
    reg  dl_sq$7$clock;
    reg  [28:0] dl_sq$8$d;
    wire  [28:0] dl_sq$8$q;
    reg  dl_sq$8$clock;
    reg  [28:0] dl_sq$9$d;
    wire  [28:0] dl_sq$9$q;
    reg  dl_sq$9$clock;
    reg  [28:0] dl_sq$10$d;
    wire  [28:0] dl_sq$10$q;
    reg  dl_sq$10$clock;
    reg  [28:0] dl_sq$11$d;
    wire  [28:0] dl_sq$11$q;
    reg  dl_sq$11$clock;
    reg  [28:0] dl_sq$12$d;
    wire  [28:0] dl_sq$12$q;
    reg  dl_sq$12$clock;
    reg  [28:0] dl_tq$0$d;
    wire  [28:0] dl_tq$0$q;
    reg  dl_tq$0$clock;
    reg  [28:0] dl_tq$1$d;
    wire  [28:0] dl_tq$1$q;
    reg  dl_tq$1$clock;
    reg  [28:0] dl_tq$2$d;
    wire  [28:0] dl_tq$2$q;
    reg  dl_tq$2$clock;
    reg  [28:0] dl_tq$3$d;
    wire  [28:0] dl_tq$3$q;
    reg  dl_tq$3$clock;
    reg  [28:0] dl_tq$4$d;
    wire  [28:0] dl_tq$4$q;
    reg  dl_tq$4$clock;
    reg  [28:0] dl_tq$5$d;
    wire  [28:0] dl_tq$5$q;
    reg  dl_tq$5$clock;
    reg  [28:0] dl_tq$6$d;
    wire  [28:0] dl_tq$6$q;
    reg  dl_tq$6$clock;
    reg  [28:0] dl_tq$7$d;
    wire  [28:0] dl_tq$7$q;
    reg  dl_tq$7$clock;
    reg  [28:0] dl_tq$8$d;
    wire  [28:0] dl_tq$8$q;
    reg  dl_tq$8$clock;
    reg  [28:0] dl_tq$9$d;
    wire  [28:0] dl_tq$9$q;
    reg  dl_tq$9$clock;
    reg  [28:0] dl_tq$10$d;
    wire  [28:0] dl_tq$10$q;
    reg  dl_tq$10$clock;
    reg  [28:0] dl_tq$11$d;
    wire  [28:0] dl_tq$11$q;
    reg  dl_tq$11$clock;
    reg  [28:0] dl_tq$12$d;
    wire  [28:0] dl_tq$12$q;
    reg  dl_tq$12$clock;
    reg  [32:0] dl_dsq_x$0$d;
    wire  [32:0] dl_dsq_x$0$q;
    reg  dl_dsq_x$0$clock;
    reg  [32:0] dl_dsq_x$1$d;
    wire  [32:0] dl_dsq_x$1$q;
    reg  dl_dsq_x$1$clock;
    reg  [32:0] dl_dsq_x$2$d;
    wire  [32:0] dl_dsq_x$2$q;
    reg  dl_dsq_x$2$clock;
    reg  [32:0] dl_dsq_x$3$d;
    wire  [32:0] dl_dsq_x$3$q;
    reg  dl_dsq_x$3$clock;
    reg  [32:0] dl_dsq_x$4$d;
    wire  [32:0] dl_dsq_x$4$q;
    reg  dl_dsq_x$4$clock;
    reg  [32:0] dl_dsq_x$5$d;
    wire  [32:0] dl_dsq_x$5$q;
    reg  dl_dsq_x$5$clock;
    reg  [32:0] dl_dsq_x$6$d;
    wire  [32:0] dl_dsq_x$6$q;
    reg  dl_dsq_x$6$clock;
    reg  [32:0] dl_dsq_x$7$d;
    wire  [32:0] dl_dsq_x$7$q;
    reg  dl_dsq_x$7$clock;
    reg  [32:0] dl_dsq_x$8$d;
    wire  [32:0] dl_dsq_x$8$q;
    reg  dl_dsq_x$8$clock;
    reg  [32:0] dl_dsq_x$9$d;
    wire  [32:0] dl_dsq_x$9$q;
    reg  dl_dsq_x$9$clock;
    reg  [32:0] dl_dsq_x$10$d;
    wire  [32:0] dl_dsq_x$10$q;
    reg  dl_dsq_x$10$clock;
    reg  [32:0] dl_dsq_x$11$d;
    wire  [32:0] dl_dsq_x$11$q;
    reg  dl_dsq_x$11$clock;
    reg  [32:0] dl_dsq_x$12$d;
    wire  [32:0] dl_dsq_x$12$q;
    reg  dl_dsq_x$12$clock;
    reg  [32:0] dl_dsq_y$0$d;
    wire  [32:0] dl_dsq_y$0$q;
    reg  dl_dsq_y$0$clock;
    reg  [32:0] dl_dsq_y$1$d;
    wire  [32:0] dl_dsq_y$1$q;
    reg  dl_dsq_y$1$clock;
    reg  [32:0] dl_dsq_y$2$d;
    wire  [32:0] dl_dsq_y$2$q;
    reg  dl_dsq_y$2$clock;
    reg  [32:0] dl_dsq_y$3$d;
    wire  [32:0] dl_dsq_y$3$q;
    reg  dl_dsq_y$3$clock;
    reg  [32:0] dl_dsq_y$4$d;
    wire  [32:0] dl_dsq_y$4$q;
    reg  dl_dsq_y$4$clock;
    reg  [32:0] dl_dsq_y$5$d;
    wire  [32:0] dl_dsq_y$5$q;
    reg  dl_dsq_y$5$clock;
    reg  [32:0] dl_dsq_y$6$d;
    wire  [32:0] dl_dsq_y$6$q;
    reg  dl_dsq_y$6$clock;
    reg  [32:0] dl_dsq_y$7$d;
    wire  [32:0] dl_dsq_y$7$q;
    reg  dl_dsq_y$7$clock;
    reg  [32:0] dl_dsq_y$8$d;
    wire  [32:0] dl_dsq_y$8$q;
    reg  dl_dsq_y$8$clock;
    reg  [32:0] dl_dsq_y$9$d;
    wire  [32:0] dl_dsq_y$9$q;
    reg  dl_dsq_y$9$clock;
    reg  [32:0] dl_dsq_y$10$d;
    wire  [32:0] dl_dsq_y$10$q;
    reg  dl_dsq_y$10$clock;
    reg  [32:0] dl_dsq_y$11$d;
    wire  [32:0] dl_dsq_y$11$q;
    reg  dl_dsq_y$11$clock;
    reg  [32:0] dl_dsq_y$12$d;
    wire  [32:0] dl_dsq_y$12$q;
    reg  dl_dsq_y$12$clock;
    reg  [32:0] dl_dtq_x$0$d;
    wire  [32:0] dl_dtq_x$0$q;
    reg  dl_dtq_x$0$clock;
    reg  [32:0] dl_dtq_x$1$d;
    wire  [32:0] dl_dtq_x$1$q;
    reg  dl_dtq_x$1$clock;
    reg  [32:0] dl_dtq_x$2$d;
    wire  [32:0] dl_dtq_x$2$q;
    reg  dl_dtq_x$2$clock;
    reg  [32:0] dl_dtq_x$3$d;
    wire  [32:0] dl_dtq_x$3$q;
    reg  dl_dtq_x$3$clock;
    reg  [32:0] dl_dtq_x$4$d;
    wire  [32:0] dl_dtq_x$4$q;
    reg  dl_dtq_x$4$clock;
    reg  [32:0] dl_dtq_x$5$d;
    wire  [32:0] dl_dtq_x$5$q;
    reg  dl_dtq_x$5$clock;
    reg  [32:0] dl_dtq_x$6$d;
    wire  [32:0] dl_dtq_x$6$q;
    reg  dl_dtq_x$6$clock;
    reg  [32:0] dl_dtq_x$7$d;
    wire  [32:0] dl_dtq_x$7$q;
    reg  dl_dtq_x$7$clock;
    reg  [32:0] dl_dtq_x$8$d;
    wire  [32:0] dl_dtq_x$8$q;
    reg  dl_dtq_x$8$clock;
    reg  [32:0] dl_dtq_x$9$d;
    wire  [32:0] dl_dtq_x$9$q;
    reg  dl_dtq_x$9$clock;
    reg  [32:0] dl_dtq_x$10$d;
    wire  [32:0] dl_dtq_x$10$q;
    reg  dl_dtq_x$10$clock;
    reg  [32:0] dl_dtq_x$11$d;
    wire  [32:0] dl_dtq_x$11$q;
    reg  dl_dtq_x$11$clock;
    reg  [32:0] dl_dtq_x$12$d;
    wire  [32:0] dl_dtq_x$12$q;
    reg  dl_dtq_x$12$clock;
    reg  [32:0] dl_dtq_y$0$d;
    wire  [32:0] dl_dtq_y$0$q;
    reg  dl_dtq_y$0$clock;
    reg  [32:0] dl_dtq_y$1$d;
    wire  [32:0] dl_dtq_y$1$q;
    reg  dl_dtq_y$1$clock;
    reg  [32:0] dl_dtq_y$2$d;
    wire  [32:0] dl_dtq_y$2$q;
    reg  dl_dtq_y$2$clock;
    reg  [32:0] dl_dtq_y$3$d;
    wire  [32:0] dl_dtq_y$3$q;
    reg  dl_dtq_y$3$clock;
    reg  [32:0] dl_dtq_y$4$d;
    wire  [32:0] dl_dtq_y$4$q;
    reg  dl_dtq_y$4$clock;
    reg  [32:0] dl_dtq_y$5$d;
    wire  [32:0] dl_dtq_y$5$q;
    reg  dl_dtq_y$5$clock;
    reg  [32:0] dl_dtq_y$6$d;
    wire  [32:0] dl_dtq_y$6$q;
    reg  dl_dtq_y$6$clock;
    reg  [32:0] dl_dtq_y$7$d;
    wire  [32:0] dl_dtq_y$7$q;
    reg  dl_dtq_y$7$clock;
    reg  [32:0] dl_dtq_y$8$d;
    wire  [32:0] dl_dtq_y$8$q;
    reg  dl_dtq_y$8$clock;
    reg  [32:0] dl_dtq_y$9$d;
    wire  [32:0] dl_dtq_y$9$q;
    reg  dl_dtq_y$9$clock;
    reg  [32:0] dl_dtq_y$10$d;
    wire  [32:0] dl_dtq_y$10$q;
    reg  dl_dtq_y$10$clock;
    reg  [32:0] dl_dtq_y$11$d;
    wire  [32:0] dl_dtq_y$11$q;
    reg  dl_dtq_y$11$clock;
    reg  [32:0] dl_dtq_y$12$d;
    wire  [32:0] dl_dtq_y$12$q;
    reg  dl_dtq_y$12$clock;
    reg  [29:0] dl_dq_x$0$d;
    wire  [29:0] dl_dq_x$0$q;
    reg  dl_dq_x$0$clock;
    reg  [29:0] dl_dq_x$1$d;
    wire  [29:0] dl_dq_x$1$q;
    reg  dl_dq_x$1$clock;
    reg  [29:0] dl_dq_x$2$d;
    wire  [29:0] dl_dq_x$2$q;
    reg  dl_dq_x$2$clock;
    reg  [29:0] dl_dq_x$3$d;
    wire  [29:0] dl_dq_x$3$q;
    reg  dl_dq_x$3$clock;
    reg  [29:0] dl_dq_x$4$d;
    wire  [29:0] dl_dq_x$4$q;
    reg  dl_dq_x$4$clock;
    reg  [29:0] dl_dq_x$5$d;
    wire  [29:0] dl_dq_x$5$q;
    reg  dl_dq_x$5$clock;
    reg  [29:0] dl_dq_x$6$d;
    wire  [29:0] dl_dq_x$6$q;
    reg  dl_dq_x$6$clock;
    reg  [29:0] dl_dq_x$7$d;
    wire  [29:0] dl_dq_x$7$q;
    reg  dl_dq_x$7$clock;
    reg  [29:0] dl_dq_x$8$d;
    wire  [29:0] dl_dq_x$8$q;
    reg  dl_dq_x$8$clock;
    reg  [29:0] dl_dq_x$9$d;
    wire  [29:0] dl_dq_x$9$q;
    reg  dl_dq_x$9$clock;
    reg  [29:0] dl_dq_x$10$d;
    wire  [29:0] dl_dq_x$10$q;
    reg  dl_dq_x$10$clock;
    reg  [29:0] dl_dq_x$11$d;
    wire  [29:0] dl_dq_x$11$q;
    reg  dl_dq_x$11$clock;
    reg  [29:0] dl_dq_x$12$d;
    wire  [29:0] dl_dq_x$12$q;
    reg  dl_dq_x$12$clock;
    reg  [29:0] dl_dq_y$0$d;
    wire  [29:0] dl_dq_y$0$q;
    reg  dl_dq_y$0$clock;
    reg  [29:0] dl_dq_y$1$d;
    wire  [29:0] dl_dq_y$1$q;
    reg  dl_dq_y$1$clock;
    reg  [29:0] dl_dq_y$2$d;
    wire  [29:0] dl_dq_y$2$q;
    reg  dl_dq_y$2$clock;
    reg  [29:0] dl_dq_y$3$d;
    wire  [29:0] dl_dq_y$3$q;
    reg  dl_dq_y$3$clock;
    reg  [29:0] dl_dq_y$4$d;
    wire  [29:0] dl_dq_y$4$q;
    reg  dl_dq_y$4$clock;
    reg  [29:0] dl_dq_y$5$d;
    wire  [29:0] dl_dq_y$5$q;
    reg  dl_dq_y$5$clock;
    reg  [29:0] dl_dq_y$6$d;
    wire  [29:0] dl_dq_y$6$q;
    reg  dl_dq_y$6$clock;
    reg  [29:0] dl_dq_y$7$d;
    wire  [29:0] dl_dq_y$7$q;
    reg  dl_dq_y$7$clock;
    reg  [29:0] dl_dq_y$8$d;
    wire  [29:0] dl_dq_y$8$q;
    reg  dl_dq_y$8$clock;
    reg  [29:0] dl_dq_y$9$d;
    wire  [29:0] dl_dq_y$9$q;
    reg  dl_dq_y$9$clock;
    reg  [29:0] dl_dq_y$10$d;
    wire  [29:0] dl_dq_y$10$q;
    reg  dl_dq_y$10$clock;
    reg  [29:0] dl_dq_y$11$d;
    wire  [29:0] dl_dq_y$11$q;
    reg  dl_dq_y$11$clock;
    reg  [29:0] dl_dq_y$12$d;
    wire  [29:0] dl_dq_y$12$q;
    reg  dl_dq_y$12$clock;
    reg  [7:0] dl_lz$0$d;
    wire  [7:0] dl_lz$0$q;
    reg  dl_lz$0$clock;
    reg  [7:0] dl_lz$1$d;
    wire  [7:0] dl_lz$1$q;
    reg  dl_lz$1$clock;
    reg  [7:0] dl_lz$2$d;
    wire  [7:0] dl_lz$2$q;
    reg  dl_lz$2$clock;
    reg  [7:0] dl_lz$3$d;
    wire  [7:0] dl_lz$3$q;
    reg  dl_lz$3$clock;
    reg  [7:0] dl_lz$4$d;
    wire  [7:0] dl_lz$4$q;
    reg  dl_lz$4$clock;
    reg  [7:0] dl_lz$5$d;
    wire  [7:0] dl_lz$5$q;
    reg  dl_lz$5$clock;
    reg  [7:0] dl_lz$6$d;
    wire  [7:0] dl_lz$6$q;
    reg  dl_lz$6$clock;
    reg  [7:0] dl_lz$7$d;
    wire  [7:0] dl_lz$7$q;
    reg  dl_lz$7$clock;
    reg  [7:0] dl_lz$8$d;
    wire  [7:0] dl_lz$8$q;
    reg  dl_lz$8$clock;
    reg  [7:0] dl_lz$9$d;
    wire  [7:0] dl_lz$9$q;
    reg  dl_lz$9$clock;
    reg  [7:0] dl_lz$10$d;
    wire  [7:0] dl_lz$10$q;
    reg  dl_lz$10$clock;
    reg  [7:0] dl_lz$11$d;
    wire  [7:0] dl_lz$11$q;
    reg  dl_lz$11$clock;
    reg  [7:0] dl_lz$12$d;
    wire  [7:0] dl_lz$12$q;
    reg  dl_lz$12$clock;
    reg  [3:0] dl_ws$0$d;
    wire  [3:0] dl_ws$0$q;
    reg  dl_ws$0$clock;
    reg  [3:0] dl_ws$1$d;
    wire  [3:0] dl_ws$1$q;
    reg  dl_ws$1$clock;
    reg  [3:0] dl_ws$2$d;
    wire  [3:0] dl_ws$2$q;
    reg  dl_ws$2$clock;
    reg  [3:0] dl_ws$3$d;
    wire  [3:0] dl_ws$3$q;
    reg  dl_ws$3$clock;
    reg  [3:0] dl_ws$4$d;
    wire  [3:0] dl_ws$4$q;
    reg  dl_ws$4$clock;
    reg  [3:0] dl_ws$5$d;
    wire  [3:0] dl_ws$5$q;
    reg  dl_ws$5$clock;
    reg  [3:0] dl_ws$6$d;
    wire  [3:0] dl_ws$6$q;
    reg  dl_ws$6$clock;
    reg  [3:0] dl_ws$7$d;
    wire  [3:0] dl_ws$7$q;
    reg  dl_ws$7$clock;
    reg  [3:0] dl_ws$8$d;
    wire  [3:0] dl_ws$8$q;
    reg  dl_ws$8$clock;
    reg  [3:0] dl_ws$9$d;
    wire  [3:0] dl_ws$9$q;
    reg  dl_ws$9$clock;
    reg  [3:0] dl_ws$10$d;
    wire  [3:0] dl_ws$10$q;
    reg  dl_ws$10$clock;
    reg  [3:0] dl_ws$11$d;
    wire  [3:0] dl_ws$11$q;
    reg  dl_ws$11$clock;
    reg  [3:0] dl_ws$12$d;
    wire  [3:0] dl_ws$12$q;
    reg  dl_ws$12$clock;
    reg  [3:0] dl_hs$0$d;
    wire  [3:0] dl_hs$0$q;
    reg  dl_hs$0$clock;
    reg  [3:0] dl_hs$1$d;
    wire  [3:0] dl_hs$1$q;
    reg  dl_hs$1$clock;
    reg  [3:0] dl_hs$2$d;
    wire  [3:0] dl_hs$2$q;
    reg  dl_hs$2$clock;
    reg  [3:0] dl_hs$3$d;
    wire  [3:0] dl_hs$3$q;
    reg  dl_hs$3$clock;
    reg  [3:0] dl_hs$4$d;
    wire  [3:0] dl_hs$4$q;
    reg  dl_hs$4$clock;
    reg  [3:0] dl_hs$5$d;
    wire  [3:0] dl_hs$5$q;
    reg  dl_hs$5$clock;
    reg  [3:0] dl_hs$6$d;
    wire  [3:0] dl_hs$6$q;
    reg  dl_hs$6$clock;
    reg  [3:0] dl_hs$7$d;
    wire  [3:0] dl_hs$7$q;
    reg  dl_hs$7$clock;
    reg  [3:0] dl_hs$8$d;
    wire  [3:0] dl_hs$8$q;
    reg  dl_hs$8$clock;
    reg  [3:0] dl_hs$9$d;
    wire  [3:0] dl_hs$9$q;
    reg  dl_hs$9$clock;
    reg  [3:0] dl_hs$10$d;
    wire  [3:0] dl_hs$10$q;
    reg  dl_hs$10$clock;
    reg  [3:0] dl_hs$11$d;
    wire  [3:0] dl_hs$11$q;
    reg  dl_hs$11$clock;
    reg  [3:0] dl_hs$12$d;
    wire  [3:0] dl_hs$12$q;
    reg  dl_hs$12$clock;
    reg  [28:0] mul_s$a;
    reg  [26:0] mul_s$b;
    wire  [55:0] mul_s$p;
    reg  [28:0] mul_t$a;
    reg  [26:0] mul_t$b;
    wire  [55:0] mul_t$p;
    reg  b1_valid$d;
    wire  b1_valid$q;
    reg  b1_valid$clock;
    reg  [55:0] b1_p$0$d;
    wire  [55:0] b1_p$0$q;
    reg  b1_p$0$clock;
    reg  [55:0] b1_p$1$d;
    wire  [55:0] b1_p$1$q;
    reg  b1_p$1$clock;
    reg  [7:0] b1_sh$d;
    wire  [7:0] b1_sh$q;
    reg  b1_sh$clock;
    reg  [32:0] b1_dxq$0$d;
    wire  [32:0] b1_dxq$0$q;
    reg  b1_dxq$0$clock;
    reg  [32:0] b1_dxq$1$d;
    wire  [32:0] b1_dxq$1$q;
    reg  b1_dxq$1$clock;
    reg  [32:0] b1_dxq$2$d;
    wire  [32:0] b1_dxq$2$q;
    reg  b1_dxq$2$clock;
    reg  [32:0] b1_dxq$3$d;
    wire  [32:0] b1_dxq$3$q;
    reg  b1_dxq$3$clock;
    reg  [29:0] b1_dq$0$d;
    wire  [29:0] b1_dq$0$q;
    reg  b1_dq$0$clock;
    reg  [29:0] b1_dq$1$d;
    wire  [29:0] b1_dq$1$q;
    reg  b1_dq$1$clock;
    reg  [7:0] b1_lz$d;
    wire  [7:0] b1_lz$q;
    reg  b1_lz$clock;
    reg  [3:0] b1_ws$d;
    wire  [3:0] b1_ws$q;
    reg  b1_ws$clock;
    reg  [3:0] b1_hs$d;
    wire  [3:0] b1_hs$q;
    reg  b1_hs$clock;
    reg  [26:0] b1_r$d;
    wire  [26:0] b1_r$q;
    reg  b1_r$clock;
    reg  b_valid$d;
    wire  b_valid$q;
    reg  b_valid$clock;
    reg  [28:0] b_st$0$d;
    wire  [28:0] b_st$0$q;
    reg  b_st$0$clock;
    reg  [28:0] b_st$1$d;
    wire  [28:0] b_st$1$q;
    reg  b_st$1$clock;
    reg  [32:0] b_dxq$0$d;
    wire  [32:0] b_dxq$0$q;
    reg  b_dxq$0$clock;
    reg  [32:0] b_dxq$1$d;
    wire  [32:0] b_dxq$1$q;
    reg  b_dxq$1$clock;
    reg  [32:0] b_dxq$2$d;
    wire  [32:0] b_dxq$2$q;
    reg  b_dxq$2$clock;
    reg  [32:0] b_dxq$3$d;
    wire  [32:0] b_dxq$3$q;
    reg  b_dxq$3$clock;
    reg  [29:0] b_dq$0$d;
    wire  [29:0] b_dq$0$q;
    reg  b_dq$0$clock;
    reg  [29:0] b_dq$1$d;
    wire  [29:0] b_dq$1$q;
    reg  b_dq$1$clock;
    reg  [7:0] b_lz$d;
    wire  [7:0] b_lz$q;
    reg  b_lz$clock;
    reg  [3:0] b_ws$d;
    wire  [3:0] b_ws$q;
    reg  b_ws$clock;
    reg  [3:0] b_hs$d;
    wire  [3:0] b_hs$q;
    reg  b_hs$clock;
    reg  [26:0] b_r$d;
    wire  [26:0] b_r$q;
    reg  b_r$clock;
    reg  [28:0] mul_g$0$a;
    reg  [29:0] mul_g$0$b;
    wire  [58:0] mul_g$0$p;
    reg  [28:0] mul_g$1$a;
    reg  [29:0] mul_g$1$b;
    wire  [58:0] mul_g$1$p;
    reg  [28:0] mul_g$2$a;
    reg  [29:0] mul_g$2$b;
    wire  [58:0] mul_g$2$p;
    reg  [28:0] mul_g$3$a;
    reg  [29:0] mul_g$3$b;
    wire  [58:0] mul_g$3$p;
    reg  c1_valid$d;
    wire  c1_valid$q;
    reg  c1_valid$clock;
    reg  [28:0] c1_st$0$d;
    wire  [28:0] c1_st$0$q;
    reg  c1_st$0$clock;
    reg  [28:0] c1_st$1$d;
    wire  [28:0] c1_st$1$q;
    reg  c1_st$1$clock;
    reg  [34:0] c1_p$0$d;
    wire  [34:0] c1_p$0$q;
    reg  c1_p$0$clock;
    reg  [34:0] c1_p$1$d;
    wire  [34:0] c1_p$1$q;
    reg  c1_p$1$clock;
    reg  [34:0] c1_p$2$d;
    wire  [34:0] c1_p$2$q;
    reg  c1_p$2$clock;
    reg  [34:0] c1_p$3$d;
    wire  [34:0] c1_p$3$q;
    reg  c1_p$3$clock;
    reg  [32:0] c1_dxq$0$d;
    wire  [32:0] c1_dxq$0$q;
    reg  c1_dxq$0$clock;
    reg  [32:0] c1_dxq$1$d;
    wire  [32:0] c1_dxq$1$q;
    reg  c1_dxq$1$clock;
    reg  [32:0] c1_dxq$2$d;
    wire  [32:0] c1_dxq$2$q;
    reg  c1_dxq$2$clock;
    reg  [32:0] c1_dxq$3$d;
    wire  [32:0] c1_dxq$3$q;
    reg  c1_dxq$3$clock;
    reg  [7:0] c1_lz$d;
    wire  [7:0] c1_lz$q;
    reg  c1_lz$clock;
    reg  [3:0] c1_ws$d;
    wire  [3:0] c1_ws$q;
    reg  c1_ws$clock;
    reg  [3:0] c1_hs$d;
    wire  [3:0] c1_hs$q;
    reg  c1_hs$clock;
    reg  [26:0] c1_r$d;
    wire  [26:0] c1_r$q;
    reg  c1_r$clock;
    reg  [32:0] num$0$dxq;
    reg  [34:0] num$0$p;
    reg  [3:0] num$0$size_log2;
    wire  [46:0] num$0$u;
    reg  [32:0] num$1$dxq;
    reg  [34:0] num$1$p;
    reg  [3:0] num$1$size_log2;
    wire  [46:0] num$1$u;
    reg  [32:0] num$2$dxq;
    reg  [34:0] num$2$p;
    reg  [3:0] num$2$size_log2;
    wire  [46:0] num$2$u;
    reg  [32:0] num$3$dxq;
    reg  [34:0] num$3$p;
    reg  [3:0] num$3$size_log2;
    wire  [46:0] num$3$u;
    reg  c_valid$d;
    wire  c_valid$q;
    reg  c_valid$clock;
    reg  [28:0] c_st$0$d;
    wire  [28:0] c_st$0$q;
    reg  c_st$0$clock;
    reg  [28:0] c_st$1$d;
    wire  [28:0] c_st$1$q;
    reg  c_st$1$clock;
    reg  [46:0] c_u$0$d;
    wire  [46:0] c_u$0$q;
    reg  c_u$0$clock;
    reg  [46:0] c_u$1$d;
    wire  [46:0] c_u$1$q;
    reg  c_u$1$clock;
    reg  [46:0] c_u$2$d;
    wire  [46:0] c_u$2$q;
    reg  c_u$2$clock;
    reg  [46:0] c_u$3$d;
    wire  [46:0] c_u$3$q;
    reg  c_u$3$clock;
    reg  [7:0] c_lz$d;
    wire  [7:0] c_lz$q;
    reg  c_lz$clock;
    reg  [26:0] c_r$d;
    wire  [26:0] c_r$q;
    reg  c_r$clock;
    reg  [47:0] mul_sq$0$a;
    reg  [47:0] mul_sq$0$b;
    wire  [95:0] mul_sq$0$p;
    reg  [47:0] mul_sq$1$a;
    reg  [47:0] mul_sq$1$b;
    wire  [95:0] mul_sq$1$p;
    reg  [47:0] mul_sq$2$a;
    reg  [47:0] mul_sq$2$b;
    wire  [95:0] mul_sq$2$p;
    reg  [47:0] mul_sq$3$a;
    reg  [47:0] mul_sq$3$b;
    wire  [95:0] mul_sq$3$p;
    reg  d_valid$d;
    wire  d_valid$q;
    reg  d_valid$clock;
    reg  [28:0] d_st$0$d;
    wire  [28:0] d_st$0$q;
    reg  d_st$0$clock;
    reg  [28:0] d_st$1$d;
    wire  [28:0] d_st$1$q;
    reg  d_st$1$clock;
    reg  [94:0] d_m$d;
    wire  [94:0] d_m$q;
    reg  d_m$clock;
    reg  [7:0] d_lz$d;
    wire  [7:0] d_lz$q;
    reg  d_lz$clock;
    reg  [26:0] d_r$d;
    wire  [26:0] d_r$q;
    reg  d_r$clock;
    reg  e1_valid$d;
    wire  e1_valid$q;
    reg  e1_valid$clock;
    reg  e1_zero$d;
    wire  e1_zero$q;
    reg  e1_zero$clock;
    reg  [28:0] e1_st$0$d;
    wire  [28:0] e1_st$0$q;
    reg  e1_st$0$clock;
    reg  [28:0] e1_st$1$d;
    wire  [28:0] e1_st$1$q;
    reg  e1_st$1$clock;
    reg  [7:0] e1_p$0$d;
    wire  [7:0] e1_p$0$q;
    reg  e1_p$0$clock;
    reg  [7:0] e1_p$1$d;
    wire  [7:0] e1_p$1$q;
    reg  e1_p$1$clock;
    reg  [9:0] e1_idx$0$d;
    wire  [9:0] e1_idx$0$q;
    reg  e1_idx$0$clock;
    reg  [9:0] e1_idx$1$d;
    wire  [9:0] e1_idx$1$q;
    reg  e1_idx$1$clock;
    reg  [7:0] e1_lz$d;
    wire  [7:0] e1_lz$q;
    reg  e1_lz$clock;
    reg  e2_valid$d;
    wire  e2_valid$q;
    reg  e2_valid$clock;
    reg  e2_zero$d;
    wire  e2_zero$q;
    reg  e2_zero$clock;
    reg  [28:0] e2_st$0$d;
    wire  [28:0] e2_st$0$q;
    reg  e2_st$0$clock;
    reg  [28:0] e2_st$1$d;
    wire  [28:0] e2_st$1$q;
    reg  e2_st$1$clock;
    reg  [7:0] e2_p$0$d;
    wire  [7:0] e2_p$0$q;
    reg  e2_p$0$clock;
    reg  [7:0] e2_p$1$d;
    wire  [7:0] e2_p$1$q;
    reg  e2_p$1$clock;
    reg  [9:0] e2_idx$0$d;
    wire  [9:0] e2_idx$0$q;
    reg  e2_idx$0$clock;
    reg  [9:0] e2_idx$1$d;
    wire  [9:0] e2_idx$1$q;
    reg  e2_idx$1$clock;
    reg  [7:0] e2_lz$d;
    wire  [7:0] e2_lz$q;
    reg  e2_lz$clock;
    reg  [9:0] log_m$address;
    reg  log_m$clock;
    wire  [11:0] log_m$data;
    reg  [9:0] log_r$address;
    reg  log_r$clock;
    wire  [11:0] log_r$data;
    reg  e_valid$d;
    wire  e_valid$q;
    reg  e_valid$clock;
    reg  [28:0] e_st$0$d;
    wire  [28:0] e_st$0$q;
    reg  e_st$0$clock;
    reg  [28:0] e_st$1$d;
    wire  [28:0] e_st$1$q;
    reg  e_st$1$clock;
    reg  [31:0] e_lambda$d;
    wire  [31:0] e_lambda$q;
    reg  e_lambda$clock;
    
    // Local signals
    reg  [20:0] qn;
    reg  [7:0] lz;
    reg  [7:0] sh;
    reg  [55:0] wide$0;
    reg  [55:0] wide$1;
    reg  [28:0] st_c$0;
    reg  [28:0] st_c$1;
    reg  [46:0] m_01;
    reg  [46:0] m_23;
    reg  [46:0] m_max;
    reg  [94:0] m_x;
    reg  [94:0] m_y;
    reg  [7:0] p_m;
    reg  [7:0] p_r;
    reg  [94:0] norm_m;
    reg  [26:0] norm_r;
    reg  [23:0] sum;
    reg  [23:0] rounded;
    reg  [23:0] lambda24;
    
    // Sub module instances
    texture_path$unit$coords$recip recip(
        .clock(recip$clock),
        .inp_valid(recip$inp_valid),
        .inp_ready(recip$inp_ready),
        .hold(recip$hold),
        .inp_n(recip$inp_n),
        .inp_d(recip$inp_d),
        .out_valid(recip$out_valid),
        .out_ready(recip$out_ready),
        .out_q(recip$out_q),
        .out_r(recip$out_r)
    );
    texture_path$unit$coords$dl_sq$0 dl_sq$0(
        .d(dl_sq$0$d),
        .q(dl_sq$0$q),
        .clock(dl_sq$0$clock)
    );
    texture_path$unit$coords$dl_sq$1 dl_sq$1(
        .d(dl_sq$1$d),
        .q(dl_sq$1$q),
        .clock(dl_sq$1$clock)
    );
    texture_path$unit$coords$dl_sq$2 dl_sq$2(
        .d(dl_sq$2$d),
        .q(dl_sq$2$q),
        .clock(dl_sq$2$clock)
    );
    texture_path$unit$coords$dl_sq$3 dl_sq$3(
        .d(dl_sq$3$d),
        .q(dl_sq$3$q),
        .clock(dl_sq$3$clock)
    );
    texture_path$unit$coords$dl_sq$4 dl_sq$4(
        .d(dl_sq$4$d),
        .q(dl_sq$4$q),
        .clock(dl_sq$4$clock)
    );
    texture_path$unit$coords$dl_sq$5 dl_sq$5(
        .d(dl_sq$5$d),
        .q(dl_sq$5$q),
        .clock(dl_sq$5$clock)
    );
    texture_path$unit$coords$dl_sq$6 dl_sq$6(
        .d(dl_sq$6$d),
        .q(dl_sq$6$q),
        .clock(dl_sq$6$clock)
    );
    texture_path$unit$coords$dl_sq$7 dl_sq$7(
        .d(dl_sq$7$d),
        .q(dl_sq$7$q),
        .clock(dl_sq$7$clock)
    );
    texture_path$unit$coords$dl_sq$8 dl_sq$8(
        .d(dl_sq$8$d),
        .q(dl_sq$8$q),
        .clock(dl_sq$8$clock)
    );
    texture_path$unit$coords$dl_sq$9 dl_sq$9(
        .d(dl_sq$9$d),
        .q(dl_sq$9$q),
        .clock(dl_sq$9$clock)
    );
    texture_path$unit$coords$dl_sq$10 dl_sq$10(
        .d(dl_sq$10$d),
        .q(dl_sq$10$q),
        .clock(dl_sq$10$clock)
    );
    texture_path$unit$coords$dl_sq$11 dl_sq$11(
        .d(dl_sq$11$d),
        .q(dl_sq$11$q),
        .clock(dl_sq$11$clock)
    );
    texture_path$unit$coords$dl_sq$12 dl_sq$12(
        .d(dl_sq$12$d),
        .q(dl_sq$12$q),
        .clock(dl_sq$12$clock)
    );
    texture_path$unit$coords$dl_tq$0 dl_tq$0(
        .d(dl_tq$0$d),
        .q(dl_tq$0$q),
        .clock(dl_tq$0$clock)
    );
    texture_path$unit$coords$dl_tq$1 dl_tq$1(
        .d(dl_tq$1$d),
        .q(dl_tq$1$q),
        .clock(dl_tq$1$clock)
    );
    texture_path$unit$coords$dl_tq$2 dl_tq$2(
        .d(dl_tq$2$d),
        .q(dl_tq$2$q),
        .clock(dl_tq$2$clock)
    );
    texture_path$unit$coords$dl_tq$3 dl_tq$3(
        .d(dl_tq$3$d),
        .q(dl_tq$3$q),
        .clock(dl_tq$3$clock)
    );
    texture_path$unit$coords$dl_tq$4 dl_tq$4(
        .d(dl_tq$4$d),
        .q(dl_tq$4$q),
        .clock(dl_tq$4$clock)
    );
    texture_path$unit$coords$dl_tq$5 dl_tq$5(
        .d(dl_tq$5$d),
        .q(dl_tq$5$q),
        .clock(dl_tq$5$clock)
    );
    texture_path$unit$coords$dl_tq$6 dl_tq$6(
        .d(dl_tq$6$d),
        .q(dl_tq$6$q),
        .clock(dl_tq$6$clock)
    );
    texture_path$unit$coords$dl_tq$7 dl_tq$7(
        .d(dl_tq$7$d),
        .q(dl_tq$7$q),
        .clock(dl_tq$7$clock)
    );
    texture_path$unit$coords$dl_tq$8 dl_tq$8(
        .d(dl_tq$8$d),
        .q(dl_tq$8$q),
        .clock(dl_tq$8$clock)
    );
    texture_path$unit$coords$dl_tq$9 dl_tq$9(
        .d(dl_tq$9$d),
        .q(dl_tq$9$q),
        .clock(dl_tq$9$clock)
    );
    texture_path$unit$coords$dl_tq$10 dl_tq$10(
        .d(dl_tq$10$d),
        .q(dl_tq$10$q),
        .clock(dl_tq$10$clock)
    );
    texture_path$unit$coords$dl_tq$11 dl_tq$11(
        .d(dl_tq$11$d),
        .q(dl_tq$11$q),
        .clock(dl_tq$11$clock)
    );
    texture_path$unit$coords$dl_tq$12 dl_tq$12(
        .d(dl_tq$12$d),
        .q(dl_tq$12$q),
        .clock(dl_tq$12$clock)
    );
    texture_path$unit$coords$dl_dsq_x$0 dl_dsq_x$0(
        .d(dl_dsq_x$0$d),
        .q(dl_dsq_x$0$q),
        .clock(dl_dsq_x$0$clock)
    );
    texture_path$unit$coords$dl_dsq_x$1 dl_dsq_x$1(
        .d(dl_dsq_x$1$d),
        .q(dl_dsq_x$1$q),
        .clock(dl_dsq_x$1$clock)
    );
    texture_path$unit$coords$dl_dsq_x$2 dl_dsq_x$2(
        .d(dl_dsq_x$2$d),
        .q(dl_dsq_x$2$q),
        .clock(dl_dsq_x$2$clock)
    );
    texture_path$unit$coords$dl_dsq_x$3 dl_dsq_x$3(
        .d(dl_dsq_x$3$d),
        .q(dl_dsq_x$3$q),
        .clock(dl_dsq_x$3$clock)
    );
    texture_path$unit$coords$dl_dsq_x$4 dl_dsq_x$4(
        .d(dl_dsq_x$4$d),
        .q(dl_dsq_x$4$q),
        .clock(dl_dsq_x$4$clock)
    );
    texture_path$unit$coords$dl_dsq_x$5 dl_dsq_x$5(
        .d(dl_dsq_x$5$d),
        .q(dl_dsq_x$5$q),
        .clock(dl_dsq_x$5$clock)
    );
    texture_path$unit$coords$dl_dsq_x$6 dl_dsq_x$6(
        .d(dl_dsq_x$6$d),
        .q(dl_dsq_x$6$q),
        .clock(dl_dsq_x$6$clock)
    );
    texture_path$unit$coords$dl_dsq_x$7 dl_dsq_x$7(
        .d(dl_dsq_x$7$d),
        .q(dl_dsq_x$7$q),
        .clock(dl_dsq_x$7$clock)
    );
    texture_path$unit$coords$dl_dsq_x$8 dl_dsq_x$8(
        .d(dl_dsq_x$8$d),
        .q(dl_dsq_x$8$q),
        .clock(dl_dsq_x$8$clock)
    );
    texture_path$unit$coords$dl_dsq_x$9 dl_dsq_x$9(
        .d(dl_dsq_x$9$d),
        .q(dl_dsq_x$9$q),
        .clock(dl_dsq_x$9$clock)
    );
    texture_path$unit$coords$dl_dsq_x$10 dl_dsq_x$10(
        .d(dl_dsq_x$10$d),
        .q(dl_dsq_x$10$q),
        .clock(dl_dsq_x$10$clock)
    );
    texture_path$unit$coords$dl_dsq_x$11 dl_dsq_x$11(
        .d(dl_dsq_x$11$d),
        .q(dl_dsq_x$11$q),
        .clock(dl_dsq_x$11$clock)
    );
    texture_path$unit$coords$dl_dsq_x$12 dl_dsq_x$12(
        .d(dl_dsq_x$12$d),
        .q(dl_dsq_x$12$q),
        .clock(dl_dsq_x$12$clock)
    );
    texture_path$unit$coords$dl_dsq_y$0 dl_dsq_y$0(
        .d(dl_dsq_y$0$d),
        .q(dl_dsq_y$0$q),
        .clock(dl_dsq_y$0$clock)
    );
    texture_path$unit$coords$dl_dsq_y$1 dl_dsq_y$1(
        .d(dl_dsq_y$1$d),
        .q(dl_dsq_y$1$q),
        .clock(dl_dsq_y$1$clock)
    );
    texture_path$unit$coords$dl_dsq_y$2 dl_dsq_y$2(
        .d(dl_dsq_y$2$d),
        .q(dl_dsq_y$2$q),
        .clock(dl_dsq_y$2$clock)
    );
    texture_path$unit$coords$dl_dsq_y$3 dl_dsq_y$3(
        .d(dl_dsq_y$3$d),
        .q(dl_dsq_y$3$q),
        .clock(dl_dsq_y$3$clock)
    );
    texture_path$unit$coords$dl_dsq_y$4 dl_dsq_y$4(
        .d(dl_dsq_y$4$d),
        .q(dl_dsq_y$4$q),
        .clock(dl_dsq_y$4$clock)
    );
    texture_path$unit$coords$dl_dsq_y$5 dl_dsq_y$5(
        .d(dl_dsq_y$5$d),
        .q(dl_dsq_y$5$q),
        .clock(dl_dsq_y$5$clock)
    );
    texture_path$unit$coords$dl_dsq_y$6 dl_dsq_y$6(
        .d(dl_dsq_y$6$d),
        .q(dl_dsq_y$6$q),
        .clock(dl_dsq_y$6$clock)
    );
    texture_path$unit$coords$dl_dsq_y$7 dl_dsq_y$7(
        .d(dl_dsq_y$7$d),
        .q(dl_dsq_y$7$q),
        .clock(dl_dsq_y$7$clock)
    );
    texture_path$unit$coords$dl_dsq_y$8 dl_dsq_y$8(
        .d(dl_dsq_y$8$d),
        .q(dl_dsq_y$8$q),
        .clock(dl_dsq_y$8$clock)
    );
    texture_path$unit$coords$dl_dsq_y$9 dl_dsq_y$9(
        .d(dl_dsq_y$9$d),
        .q(dl_dsq_y$9$q),
        .clock(dl_dsq_y$9$clock)
    );
    texture_path$unit$coords$dl_dsq_y$10 dl_dsq_y$10(
        .d(dl_dsq_y$10$d),
        .q(dl_dsq_y$10$q),
        .clock(dl_dsq_y$10$clock)
    );
    texture_path$unit$coords$dl_dsq_y$11 dl_dsq_y$11(
        .d(dl_dsq_y$11$d),
        .q(dl_dsq_y$11$q),
        .clock(dl_dsq_y$11$clock)
    );
    texture_path$unit$coords$dl_dsq_y$12 dl_dsq_y$12(
        .d(dl_dsq_y$12$d),
        .q(dl_dsq_y$12$q),
        .clock(dl_dsq_y$12$clock)
    );
    texture_path$unit$coords$dl_dtq_x$0 dl_dtq_x$0(
        .d(dl_dtq_x$0$d),
        .q(dl_dtq_x$0$q),
        .clock(dl_dtq_x$0$clock)
    );
    texture_path$unit$coords$dl_dtq_x$1 dl_dtq_x$1(
        .d(dl_dtq_x$1$d),
        .q(dl_dtq_x$1$q),
        .clock(dl_dtq_x$1$clock)
    );
    texture_path$unit$coords$dl_dtq_x$2 dl_dtq_x$2(
        .d(dl_dtq_x$2$d),
        .q(dl_dtq_x$2$q),
        .clock(dl_dtq_x$2$clock)
    );
    texture_path$unit$coords$dl_dtq_x$3 dl_dtq_x$3(
        .d(dl_dtq_x$3$d),
        .q(dl_dtq_x$3$q),
        .clock(dl_dtq_x$3$clock)
    );
    texture_path$unit$coords$dl_dtq_x$4 dl_dtq_x$4(
        .d(dl_dtq_x$4$d),
        .q(dl_dtq_x$4$q),
        .clock(dl_dtq_x$4$clock)
    );
    texture_path$unit$coords$dl_dtq_x$5 dl_dtq_x$5(
        .d(dl_dtq_x$5$d),
        .q(dl_dtq_x$5$q),
        .clock(dl_dtq_x$5$clock)
    );
    texture_path$unit$coords$dl_dtq_x$6 dl_dtq_x$6(
        .d(dl_dtq_x$6$d),
        .q(dl_dtq_x$6$q),
        .clock(dl_dtq_x$6$clock)
    );
    texture_path$unit$coords$dl_dtq_x$7 dl_dtq_x$7(
        .d(dl_dtq_x$7$d),
        .q(dl_dtq_x$7$q),
        .clock(dl_dtq_x$7$clock)
    );
    texture_path$unit$coords$dl_dtq_x$8 dl_dtq_x$8(
        .d(dl_dtq_x$8$d),
        .q(dl_dtq_x$8$q),
        .clock(dl_dtq_x$8$clock)
    );
    texture_path$unit$coords$dl_dtq_x$9 dl_dtq_x$9(
        .d(dl_dtq_x$9$d),
        .q(dl_dtq_x$9$q),
        .clock(dl_dtq_x$9$clock)
    );
    texture_path$unit$coords$dl_dtq_x$10 dl_dtq_x$10(
        .d(dl_dtq_x$10$d),
        .q(dl_dtq_x$10$q),
        .clock(dl_dtq_x$10$clock)
    );
    texture_path$unit$coords$dl_dtq_x$11 dl_dtq_x$11(
        .d(dl_dtq_x$11$d),
        .q(dl_dtq_x$11$q),
        .clock(dl_dtq_x$11$clock)
    );
    texture_path$unit$coords$dl_dtq_x$12 dl_dtq_x$12(
        .d(dl_dtq_x$12$d),
        .q(dl_dtq_x$12$q),
        .clock(dl_dtq_x$12$clock)
    );
    texture_path$unit$coords$dl_dtq_y$0 dl_dtq_y$0(
        .d(dl_dtq_y$0$d),
        .q(dl_dtq_y$0$q),
        .clock(dl_dtq_y$0$clock)
    );
    texture_path$unit$coords$dl_dtq_y$1 dl_dtq_y$1(
        .d(dl_dtq_y$1$d),
        .q(dl_dtq_y$1$q),
        .clock(dl_dtq_y$1$clock)
    );
    texture_path$unit$coords$dl_dtq_y$2 dl_dtq_y$2(
        .d(dl_dtq_y$2$d),
        .q(dl_dtq_y$2$q),
        .clock(dl_dtq_y$2$clock)
    );
    texture_path$unit$coords$dl_dtq_y$3 dl_dtq_y$3(
        .d(dl_dtq_y$3$d),
        .q(dl_dtq_y$3$q),
        .clock(dl_dtq_y$3$clock)
    );
    texture_path$unit$coords$dl_dtq_y$4 dl_dtq_y$4(
        .d(dl_dtq_y$4$d),
        .q(dl_dtq_y$4$q),
        .clock(dl_dtq_y$4$clock)
    );
    texture_path$unit$coords$dl_dtq_y$5 dl_dtq_y$5(
        .d(dl_dtq_y$5$d),
        .q(dl_dtq_y$5$q),
        .clock(dl_dtq_y$5$clock)
    );
    texture_path$unit$coords$dl_dtq_y$6 dl_dtq_y$6(
        .d(dl_dtq_y$6$d),
        .q(dl_dtq_y$6$q),
        .clock(dl_dtq_y$6$clock)
    );
    texture_path$unit$coords$dl_dtq_y$7 dl_dtq_y$7(
        .d(dl_dtq_y$7$d),
        .q(dl_dtq_y$7$q),
        .clock(dl_dtq_y$7$clock)
    );
    texture_path$unit$coords$dl_dtq_y$8 dl_dtq_y$8(
        .d(dl_dtq_y$8$d),
        .q(dl_dtq_y$8$q),
        .clock(dl_dtq_y$8$clock)
    );
    texture_path$unit$coords$dl_dtq_y$9 dl_dtq_y$9(
        .d(dl_dtq_y$9$d),
        .q(dl_dtq_y$9$q),
        .clock(dl_dtq_y$9$clock)
    );
    texture_path$unit$coords$dl_dtq_y$10 dl_dtq_y$10(
        .d(dl_dtq_y$10$d),
        .q(dl_dtq_y$10$q),
        .clock(dl_dtq_y$10$clock)
    );
    texture_path$unit$coords$dl_dtq_y$11 dl_dtq_y$11(
        .d(dl_dtq_y$11$d),
        .q(dl_dtq_y$11$q),
        .clock(dl_dtq_y$11$clock)
    );
    texture_path$unit$coords$dl_dtq_y$12 dl_dtq_y$12(
        .d(dl_dtq_y$12$d),
        .q(dl_dtq_y$12$q),
        .clock(dl_dtq_y$12$clock)
    );
    texture_path$unit$coords$dl_dq_x$0 dl_dq_x$0(
        .d(dl_dq_x$0$d),
        .q(dl_dq_x$0$q),
        .clock(dl_dq_x$0$clock)
    );
    texture_path$unit$coords$dl_dq_x$1 dl_dq_x$1(
        .d(dl_dq_x$1$d),
        .q(dl_dq_x$1$q),
        .clock(dl_dq_x$1$clock)
    );
    texture_path$unit$coords$dl_dq_x$2 dl_dq_x$2(
        .d(dl_dq_x$2$d),
        .q(dl_dq_x$2$q),
        .clock(dl_dq_x$2$clock)
    );
    texture_path$unit$coords$dl_dq_x$3 dl_dq_x$3(
        .d(dl_dq_x$3$d),
        .q(dl_dq_x$3$q),
        .clock(dl_dq_x$3$clock)
    );
    texture_path$unit$coords$dl_dq_x$4 dl_dq_x$4(
        .d(dl_dq_x$4$d),
        .q(dl_dq_x$4$q),
        .clock(dl_dq_x$4$clock)
    );
    texture_path$unit$coords$dl_dq_x$5 dl_dq_x$5(
        .d(dl_dq_x$5$d),
        .q(dl_dq_x$5$q),
        .clock(dl_dq_x$5$clock)
    );
    texture_path$unit$coords$dl_dq_x$6 dl_dq_x$6(
        .d(dl_dq_x$6$d),
        .q(dl_dq_x$6$q),
        .clock(dl_dq_x$6$clock)
    );
    texture_path$unit$coords$dl_dq_x$7 dl_dq_x$7(
        .d(dl_dq_x$7$d),
        .q(dl_dq_x$7$q),
        .clock(dl_dq_x$7$clock)
    );
    texture_path$unit$coords$dl_dq_x$8 dl_dq_x$8(
        .d(dl_dq_x$8$d),
        .q(dl_dq_x$8$q),
        .clock(dl_dq_x$8$clock)
    );
    texture_path$unit$coords$dl_dq_x$9 dl_dq_x$9(
        .d(dl_dq_x$9$d),
        .q(dl_dq_x$9$q),
        .clock(dl_dq_x$9$clock)
    );
    texture_path$unit$coords$dl_dq_x$10 dl_dq_x$10(
        .d(dl_dq_x$10$d),
        .q(dl_dq_x$10$q),
        .clock(dl_dq_x$10$clock)
    );
    texture_path$unit$coords$dl_dq_x$11 dl_dq_x$11(
        .d(dl_dq_x$11$d),
        .q(dl_dq_x$11$q),
        .clock(dl_dq_x$11$clock)
    );
    texture_path$unit$coords$dl_dq_x$12 dl_dq_x$12(
        .d(dl_dq_x$12$d),
        .q(dl_dq_x$12$q),
        .clock(dl_dq_x$12$clock)
    );
    texture_path$unit$coords$dl_dq_y$0 dl_dq_y$0(
        .d(dl_dq_y$0$d),
        .q(dl_dq_y$0$q),
        .clock(dl_dq_y$0$clock)
    );
    texture_path$unit$coords$dl_dq_y$1 dl_dq_y$1(
        .d(dl_dq_y$1$d),
        .q(dl_dq_y$1$q),
        .clock(dl_dq_y$1$clock)
    );
    texture_path$unit$coords$dl_dq_y$2 dl_dq_y$2(
        .d(dl_dq_y$2$d),
        .q(dl_dq_y$2$q),
        .clock(dl_dq_y$2$clock)
    );
    texture_path$unit$coords$dl_dq_y$3 dl_dq_y$3(
        .d(dl_dq_y$3$d),
        .q(dl_dq_y$3$q),
        .clock(dl_dq_y$3$clock)
    );
    texture_path$unit$coords$dl_dq_y$4 dl_dq_y$4(
        .d(dl_dq_y$4$d),
        .q(dl_dq_y$4$q),
        .clock(dl_dq_y$4$clock)
    );
    texture_path$unit$coords$dl_dq_y$5 dl_dq_y$5(
        .d(dl_dq_y$5$d),
        .q(dl_dq_y$5$q),
        .clock(dl_dq_y$5$clock)
    );
    texture_path$unit$coords$dl_dq_y$6 dl_dq_y$6(
        .d(dl_dq_y$6$d),
        .q(dl_dq_y$6$q),
        .clock(dl_dq_y$6$clock)
    );
    texture_path$unit$coords$dl_dq_y$7 dl_dq_y$7(
        .d(dl_dq_y$7$d),
        .q(dl_dq_y$7$q),
        .clock(dl_dq_y$7$clock)
    );
    texture_path$unit$coords$dl_dq_y$8 dl_dq_y$8(
        .d(dl_dq_y$8$d),
        .q(dl_dq_y$8$q),
        .clock(dl_dq_y$8$clock)
    );
    texture_path$unit$coords$dl_dq_y$9 dl_dq_y$9(
        .d(dl_dq_y$9$d),
        .q(dl_dq_y$9$q),
        .clock(dl_dq_y$9$clock)
    );
    texture_path$unit$coords$dl_dq_y$10 dl_dq_y$10(
        .d(dl_dq_y$10$d),
        .q(dl_dq_y$10$q),
        .clock(dl_dq_y$10$clock)
    );
    texture_path$unit$coords$dl_dq_y$11 dl_dq_y$11(
        .d(dl_dq_y$11$d),
        .q(dl_dq_y$11$q),
        .clock(dl_dq_y$11$clock)
    );
    texture_path$unit$coords$dl_dq_y$12 dl_dq_y$12(
        .d(dl_dq_y$12$d),
        .q(dl_dq_y$12$q),
        .clock(dl_dq_y$12$clock)
    );
    texture_path$unit$coords$dl_lz$0 dl_lz$0(
        .d(dl_lz$0$d),
        .q(dl_lz$0$q),
        .clock(dl_lz$0$clock)
    );
    texture_path$unit$coords$dl_lz$1 dl_lz$1(
        .d(dl_lz$1$d),
        .q(dl_lz$1$q),
        .clock(dl_lz$1$clock)
    );
    texture_path$unit$coords$dl_lz$2 dl_lz$2(
        .d(dl_lz$2$d),
        .q(dl_lz$2$q),
        .clock(dl_lz$2$clock)
    );
    texture_path$unit$coords$dl_lz$3 dl_lz$3(
        .d(dl_lz$3$d),
        .q(dl_lz$3$q),
        .clock(dl_lz$3$clock)
    );
    texture_path$unit$coords$dl_lz$4 dl_lz$4(
        .d(dl_lz$4$d),
        .q(dl_lz$4$q),
        .clock(dl_lz$4$clock)
    );
    texture_path$unit$coords$dl_lz$5 dl_lz$5(
        .d(dl_lz$5$d),
        .q(dl_lz$5$q),
        .clock(dl_lz$5$clock)
    );
    texture_path$unit$coords$dl_lz$6 dl_lz$6(
        .d(dl_lz$6$d),
        .q(dl_lz$6$q),
        .clock(dl_lz$6$clock)
    );
    texture_path$unit$coords$dl_lz$7 dl_lz$7(
        .d(dl_lz$7$d),
        .q(dl_lz$7$q),
        .clock(dl_lz$7$clock)
    );
    texture_path$unit$coords$dl_lz$8 dl_lz$8(
        .d(dl_lz$8$d),
        .q(dl_lz$8$q),
        .clock(dl_lz$8$clock)
    );
    texture_path$unit$coords$dl_lz$9 dl_lz$9(
        .d(dl_lz$9$d),
        .q(dl_lz$9$q),
        .clock(dl_lz$9$clock)
    );
    texture_path$unit$coords$dl_lz$10 dl_lz$10(
        .d(dl_lz$10$d),
        .q(dl_lz$10$q),
        .clock(dl_lz$10$clock)
    );
    texture_path$unit$coords$dl_lz$11 dl_lz$11(
        .d(dl_lz$11$d),
        .q(dl_lz$11$q),
        .clock(dl_lz$11$clock)
    );
    texture_path$unit$coords$dl_lz$12 dl_lz$12(
        .d(dl_lz$12$d),
        .q(dl_lz$12$q),
        .clock(dl_lz$12$clock)
    );
    texture_path$unit$coords$dl_ws$0 dl_ws$0(
        .d(dl_ws$0$d),
        .q(dl_ws$0$q),
        .clock(dl_ws$0$clock)
    );
    texture_path$unit$coords$dl_ws$1 dl_ws$1(
        .d(dl_ws$1$d),
        .q(dl_ws$1$q),
        .clock(dl_ws$1$clock)
    );
    texture_path$unit$coords$dl_ws$2 dl_ws$2(
        .d(dl_ws$2$d),
        .q(dl_ws$2$q),
        .clock(dl_ws$2$clock)
    );
    texture_path$unit$coords$dl_ws$3 dl_ws$3(
        .d(dl_ws$3$d),
        .q(dl_ws$3$q),
        .clock(dl_ws$3$clock)
    );
    texture_path$unit$coords$dl_ws$4 dl_ws$4(
        .d(dl_ws$4$d),
        .q(dl_ws$4$q),
        .clock(dl_ws$4$clock)
    );
    texture_path$unit$coords$dl_ws$5 dl_ws$5(
        .d(dl_ws$5$d),
        .q(dl_ws$5$q),
        .clock(dl_ws$5$clock)
    );
    texture_path$unit$coords$dl_ws$6 dl_ws$6(
        .d(dl_ws$6$d),
        .q(dl_ws$6$q),
        .clock(dl_ws$6$clock)
    );
    texture_path$unit$coords$dl_ws$7 dl_ws$7(
        .d(dl_ws$7$d),
        .q(dl_ws$7$q),
        .clock(dl_ws$7$clock)
    );
    texture_path$unit$coords$dl_ws$8 dl_ws$8(
        .d(dl_ws$8$d),
        .q(dl_ws$8$q),
        .clock(dl_ws$8$clock)
    );
    texture_path$unit$coords$dl_ws$9 dl_ws$9(
        .d(dl_ws$9$d),
        .q(dl_ws$9$q),
        .clock(dl_ws$9$clock)
    );
    texture_path$unit$coords$dl_ws$10 dl_ws$10(
        .d(dl_ws$10$d),
        .q(dl_ws$10$q),
        .clock(dl_ws$10$clock)
    );
    texture_path$unit$coords$dl_ws$11 dl_ws$11(
        .d(dl_ws$11$d),
        .q(dl_ws$11$q),
        .clock(dl_ws$11$clock)
    );
    texture_path$unit$coords$dl_ws$12 dl_ws$12(
        .d(dl_ws$12$d),
        .q(dl_ws$12$q),
        .clock(dl_ws$12$clock)
    );
    texture_path$unit$coords$dl_hs$0 dl_hs$0(
        .d(dl_hs$0$d),
        .q(dl_hs$0$q),
        .clock(dl_hs$0$clock)
    );
    texture_path$unit$coords$dl_hs$1 dl_hs$1(
        .d(dl_hs$1$d),
        .q(dl_hs$1$q),
        .clock(dl_hs$1$clock)
    );
    texture_path$unit$coords$dl_hs$2 dl_hs$2(
        .d(dl_hs$2$d),
        .q(dl_hs$2$q),
        .clock(dl_hs$2$clock)
    );
    texture_path$unit$coords$dl_hs$3 dl_hs$3(
        .d(dl_hs$3$d),
        .q(dl_hs$3$q),
        .clock(dl_hs$3$clock)
    );
    texture_path$unit$coords$dl_hs$4 dl_hs$4(
        .d(dl_hs$4$d),
        .q(dl_hs$4$q),
        .clock(dl_hs$4$clock)
    );
    texture_path$unit$coords$dl_hs$5 dl_hs$5(
        .d(dl_hs$5$d),
        .q(dl_hs$5$q),
        .clock(dl_hs$5$clock)
    );
    texture_path$unit$coords$dl_hs$6 dl_hs$6(
        .d(dl_hs$6$d),
        .q(dl_hs$6$q),
        .clock(dl_hs$6$clock)
    );
    texture_path$unit$coords$dl_hs$7 dl_hs$7(
        .d(dl_hs$7$d),
        .q(dl_hs$7$q),
        .clock(dl_hs$7$clock)
    );
    texture_path$unit$coords$dl_hs$8 dl_hs$8(
        .d(dl_hs$8$d),
        .q(dl_hs$8$q),
        .clock(dl_hs$8$clock)
    );
    texture_path$unit$coords$dl_hs$9 dl_hs$9(
        .d(dl_hs$9$d),
        .q(dl_hs$9$q),
        .clock(dl_hs$9$clock)
    );
    texture_path$unit$coords$dl_hs$10 dl_hs$10(
        .d(dl_hs$10$d),
        .q(dl_hs$10$q),
        .clock(dl_hs$10$clock)
    );
    texture_path$unit$coords$dl_hs$11 dl_hs$11(
        .d(dl_hs$11$d),
        .q(dl_hs$11$q),
        .clock(dl_hs$11$clock)
    );
    texture_path$unit$coords$dl_hs$12 dl_hs$12(
        .d(dl_hs$12$d),
        .q(dl_hs$12$q),
        .clock(dl_hs$12$clock)
    );
    texture_path$unit$coords$mul_s mul_s(
        .a(mul_s$a),
        .b(mul_s$b),
        .p(mul_s$p)
    );
    texture_path$unit$coords$mul_t mul_t(
        .a(mul_t$a),
        .b(mul_t$b),
        .p(mul_t$p)
    );
    texture_path$unit$coords$b1_valid b1_valid(
        .d(b1_valid$d),
        .q(b1_valid$q),
        .clock(b1_valid$clock)
    );
    texture_path$unit$coords$b1_p$0 b1_p$0(
        .d(b1_p$0$d),
        .q(b1_p$0$q),
        .clock(b1_p$0$clock)
    );
    texture_path$unit$coords$b1_p$1 b1_p$1(
        .d(b1_p$1$d),
        .q(b1_p$1$q),
        .clock(b1_p$1$clock)
    );
    texture_path$unit$coords$b1_sh b1_sh(
        .d(b1_sh$d),
        .q(b1_sh$q),
        .clock(b1_sh$clock)
    );
    texture_path$unit$coords$b1_dxq$0 b1_dxq$0(
        .d(b1_dxq$0$d),
        .q(b1_dxq$0$q),
        .clock(b1_dxq$0$clock)
    );
    texture_path$unit$coords$b1_dxq$1 b1_dxq$1(
        .d(b1_dxq$1$d),
        .q(b1_dxq$1$q),
        .clock(b1_dxq$1$clock)
    );
    texture_path$unit$coords$b1_dxq$2 b1_dxq$2(
        .d(b1_dxq$2$d),
        .q(b1_dxq$2$q),
        .clock(b1_dxq$2$clock)
    );
    texture_path$unit$coords$b1_dxq$3 b1_dxq$3(
        .d(b1_dxq$3$d),
        .q(b1_dxq$3$q),
        .clock(b1_dxq$3$clock)
    );
    texture_path$unit$coords$b1_dq$0 b1_dq$0(
        .d(b1_dq$0$d),
        .q(b1_dq$0$q),
        .clock(b1_dq$0$clock)
    );
    texture_path$unit$coords$b1_dq$1 b1_dq$1(
        .d(b1_dq$1$d),
        .q(b1_dq$1$q),
        .clock(b1_dq$1$clock)
    );
    texture_path$unit$coords$b1_lz b1_lz(
        .d(b1_lz$d),
        .q(b1_lz$q),
        .clock(b1_lz$clock)
    );
    texture_path$unit$coords$b1_ws b1_ws(
        .d(b1_ws$d),
        .q(b1_ws$q),
        .clock(b1_ws$clock)
    );
    texture_path$unit$coords$b1_hs b1_hs(
        .d(b1_hs$d),
        .q(b1_hs$q),
        .clock(b1_hs$clock)
    );
    texture_path$unit$coords$b1_r b1_r(
        .d(b1_r$d),
        .q(b1_r$q),
        .clock(b1_r$clock)
    );
    texture_path$unit$coords$b_valid b_valid(
        .d(b_valid$d),
        .q(b_valid$q),
        .clock(b_valid$clock)
    );
    texture_path$unit$coords$b_st$0 b_st$0(
        .d(b_st$0$d),
        .q(b_st$0$q),
        .clock(b_st$0$clock)
    );
    texture_path$unit$coords$b_st$1 b_st$1(
        .d(b_st$1$d),
        .q(b_st$1$q),
        .clock(b_st$1$clock)
    );
    texture_path$unit$coords$b_dxq$0 b_dxq$0(
        .d(b_dxq$0$d),
        .q(b_dxq$0$q),
        .clock(b_dxq$0$clock)
    );
    texture_path$unit$coords$b_dxq$1 b_dxq$1(
        .d(b_dxq$1$d),
        .q(b_dxq$1$q),
        .clock(b_dxq$1$clock)
    );
    texture_path$unit$coords$b_dxq$2 b_dxq$2(
        .d(b_dxq$2$d),
        .q(b_dxq$2$q),
        .clock(b_dxq$2$clock)
    );
    texture_path$unit$coords$b_dxq$3 b_dxq$3(
        .d(b_dxq$3$d),
        .q(b_dxq$3$q),
        .clock(b_dxq$3$clock)
    );
    texture_path$unit$coords$b_dq$0 b_dq$0(
        .d(b_dq$0$d),
        .q(b_dq$0$q),
        .clock(b_dq$0$clock)
    );
    texture_path$unit$coords$b_dq$1 b_dq$1(
        .d(b_dq$1$d),
        .q(b_dq$1$q),
        .clock(b_dq$1$clock)
    );
    texture_path$unit$coords$b_lz b_lz(
        .d(b_lz$d),
        .q(b_lz$q),
        .clock(b_lz$clock)
    );
    texture_path$unit$coords$b_ws b_ws(
        .d(b_ws$d),
        .q(b_ws$q),
        .clock(b_ws$clock)
    );
    texture_path$unit$coords$b_hs b_hs(
        .d(b_hs$d),
        .q(b_hs$q),
        .clock(b_hs$clock)
    );
    texture_path$unit$coords$b_r b_r(
        .d(b_r$d),
        .q(b_r$q),
        .clock(b_r$clock)
    );
    texture_path$unit$coords$mul_g$0 mul_g$0(
        .a(mul_g$0$a),
        .b(mul_g$0$b),
        .p(mul_g$0$p)
    );
    texture_path$unit$coords$mul_g$1 mul_g$1(
        .a(mul_g$1$a),
        .b(mul_g$1$b),
        .p(mul_g$1$p)
    );
    texture_path$unit$coords$mul_g$2 mul_g$2(
        .a(mul_g$2$a),
        .b(mul_g$2$b),
        .p(mul_g$2$p)
    );
    texture_path$unit$coords$mul_g$3 mul_g$3(
        .a(mul_g$3$a),
        .b(mul_g$3$b),
        .p(mul_g$3$p)
    );
    texture_path$unit$coords$c1_valid c1_valid(
        .d(c1_valid$d),
        .q(c1_valid$q),
        .clock(c1_valid$clock)
    );
    texture_path$unit$coords$c1_st$0 c1_st$0(
        .d(c1_st$0$d),
        .q(c1_st$0$q),
        .clock(c1_st$0$clock)
    );
    texture_path$unit$coords$c1_st$1 c1_st$1(
        .d(c1_st$1$d),
        .q(c1_st$1$q),
        .clock(c1_st$1$clock)
    );
    texture_path$unit$coords$c1_p$0 c1_p$0(
        .d(c1_p$0$d),
        .q(c1_p$0$q),
        .clock(c1_p$0$clock)
    );
    texture_path$unit$coords$c1_p$1 c1_p$1(
        .d(c1_p$1$d),
        .q(c1_p$1$q),
        .clock(c1_p$1$clock)
    );
    texture_path$unit$coords$c1_p$2 c1_p$2(
        .d(c1_p$2$d),
        .q(c1_p$2$q),
        .clock(c1_p$2$clock)
    );
    texture_path$unit$coords$c1_p$3 c1_p$3(
        .d(c1_p$3$d),
        .q(c1_p$3$q),
        .clock(c1_p$3$clock)
    );
    texture_path$unit$coords$c1_dxq$0 c1_dxq$0(
        .d(c1_dxq$0$d),
        .q(c1_dxq$0$q),
        .clock(c1_dxq$0$clock)
    );
    texture_path$unit$coords$c1_dxq$1 c1_dxq$1(
        .d(c1_dxq$1$d),
        .q(c1_dxq$1$q),
        .clock(c1_dxq$1$clock)
    );
    texture_path$unit$coords$c1_dxq$2 c1_dxq$2(
        .d(c1_dxq$2$d),
        .q(c1_dxq$2$q),
        .clock(c1_dxq$2$clock)
    );
    texture_path$unit$coords$c1_dxq$3 c1_dxq$3(
        .d(c1_dxq$3$d),
        .q(c1_dxq$3$q),
        .clock(c1_dxq$3$clock)
    );
    texture_path$unit$coords$c1_lz c1_lz(
        .d(c1_lz$d),
        .q(c1_lz$q),
        .clock(c1_lz$clock)
    );
    texture_path$unit$coords$c1_ws c1_ws(
        .d(c1_ws$d),
        .q(c1_ws$q),
        .clock(c1_ws$clock)
    );
    texture_path$unit$coords$c1_hs c1_hs(
        .d(c1_hs$d),
        .q(c1_hs$q),
        .clock(c1_hs$clock)
    );
    texture_path$unit$coords$c1_r c1_r(
        .d(c1_r$d),
        .q(c1_r$q),
        .clock(c1_r$clock)
    );
    texture_path$unit$coords$num$0 num$0(
        .dxq(num$0$dxq),
        .p(num$0$p),
        .size_log2(num$0$size_log2),
        .u(num$0$u)
    );
    texture_path$unit$coords$num$1 num$1(
        .dxq(num$1$dxq),
        .p(num$1$p),
        .size_log2(num$1$size_log2),
        .u(num$1$u)
    );
    texture_path$unit$coords$num$2 num$2(
        .dxq(num$2$dxq),
        .p(num$2$p),
        .size_log2(num$2$size_log2),
        .u(num$2$u)
    );
    texture_path$unit$coords$num$3 num$3(
        .dxq(num$3$dxq),
        .p(num$3$p),
        .size_log2(num$3$size_log2),
        .u(num$3$u)
    );
    texture_path$unit$coords$c_valid c_valid(
        .d(c_valid$d),
        .q(c_valid$q),
        .clock(c_valid$clock)
    );
    texture_path$unit$coords$c_st$0 c_st$0(
        .d(c_st$0$d),
        .q(c_st$0$q),
        .clock(c_st$0$clock)
    );
    texture_path$unit$coords$c_st$1 c_st$1(
        .d(c_st$1$d),
        .q(c_st$1$q),
        .clock(c_st$1$clock)
    );
    texture_path$unit$coords$c_u$0 c_u$0(
        .d(c_u$0$d),
        .q(c_u$0$q),
        .clock(c_u$0$clock)
    );
    texture_path$unit$coords$c_u$1 c_u$1(
        .d(c_u$1$d),
        .q(c_u$1$q),
        .clock(c_u$1$clock)
    );
    texture_path$unit$coords$c_u$2 c_u$2(
        .d(c_u$2$d),
        .q(c_u$2$q),
        .clock(c_u$2$clock)
    );
    texture_path$unit$coords$c_u$3 c_u$3(
        .d(c_u$3$d),
        .q(c_u$3$q),
        .clock(c_u$3$clock)
    );
    texture_path$unit$coords$c_lz c_lz(
        .d(c_lz$d),
        .q(c_lz$q),
        .clock(c_lz$clock)
    );
    texture_path$unit$coords$c_r c_r(
        .d(c_r$d),
        .q(c_r$q),
        .clock(c_r$clock)
    );
    texture_path$unit$coords$mul_sq$0 mul_sq$0(
        .a(mul_sq$0$a),
        .b(mul_sq$0$b),
        .p(mul_sq$0$p)
    );
    texture_path$unit$coords$mul_sq$1 mul_sq$1(
        .a(mul_sq$1$a),
        .b(mul_sq$1$b),
        .p(mul_sq$1$p)
    );
    texture_path$unit$coords$mul_sq$2 mul_sq$2(
        .a(mul_sq$2$a),
        .b(mul_sq$2$b),
        .p(mul_sq$2$p)
    );
    texture_path$unit$coords$mul_sq$3 mul_sq$3(
        .a(mul_sq$3$a),
        .b(mul_sq$3$b),
        .p(mul_sq$3$p)
    );
    texture_path$unit$coords$d_valid d_valid(
        .d(d_valid$d),
        .q(d_valid$q),
        .clock(d_valid$clock)
    );
    texture_path$unit$coords$d_st$0 d_st$0(
        .d(d_st$0$d),
        .q(d_st$0$q),
        .clock(d_st$0$clock)
    );
    texture_path$unit$coords$d_st$1 d_st$1(
        .d(d_st$1$d),
        .q(d_st$1$q),
        .clock(d_st$1$clock)
    );
    texture_path$unit$coords$d_m d_m(
        .d(d_m$d),
        .q(d_m$q),
        .clock(d_m$clock)
    );
    texture_path$unit$coords$d_lz d_lz(
        .d(d_lz$d),
        .q(d_lz$q),
        .clock(d_lz$clock)
    );
    texture_path$unit$coords$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    texture_path$unit$coords$e1_valid e1_valid(
        .d(e1_valid$d),
        .q(e1_valid$q),
        .clock(e1_valid$clock)
    );
    texture_path$unit$coords$e1_zero e1_zero(
        .d(e1_zero$d),
        .q(e1_zero$q),
        .clock(e1_zero$clock)
    );
    texture_path$unit$coords$e1_st$0 e1_st$0(
        .d(e1_st$0$d),
        .q(e1_st$0$q),
        .clock(e1_st$0$clock)
    );
    texture_path$unit$coords$e1_st$1 e1_st$1(
        .d(e1_st$1$d),
        .q(e1_st$1$q),
        .clock(e1_st$1$clock)
    );
    texture_path$unit$coords$e1_p$0 e1_p$0(
        .d(e1_p$0$d),
        .q(e1_p$0$q),
        .clock(e1_p$0$clock)
    );
    texture_path$unit$coords$e1_p$1 e1_p$1(
        .d(e1_p$1$d),
        .q(e1_p$1$q),
        .clock(e1_p$1$clock)
    );
    texture_path$unit$coords$e1_idx$0 e1_idx$0(
        .d(e1_idx$0$d),
        .q(e1_idx$0$q),
        .clock(e1_idx$0$clock)
    );
    texture_path$unit$coords$e1_idx$1 e1_idx$1(
        .d(e1_idx$1$d),
        .q(e1_idx$1$q),
        .clock(e1_idx$1$clock)
    );
    texture_path$unit$coords$e1_lz e1_lz(
        .d(e1_lz$d),
        .q(e1_lz$q),
        .clock(e1_lz$clock)
    );
    texture_path$unit$coords$e2_valid e2_valid(
        .d(e2_valid$d),
        .q(e2_valid$q),
        .clock(e2_valid$clock)
    );
    texture_path$unit$coords$e2_zero e2_zero(
        .d(e2_zero$d),
        .q(e2_zero$q),
        .clock(e2_zero$clock)
    );
    texture_path$unit$coords$e2_st$0 e2_st$0(
        .d(e2_st$0$d),
        .q(e2_st$0$q),
        .clock(e2_st$0$clock)
    );
    texture_path$unit$coords$e2_st$1 e2_st$1(
        .d(e2_st$1$d),
        .q(e2_st$1$q),
        .clock(e2_st$1$clock)
    );
    texture_path$unit$coords$e2_p$0 e2_p$0(
        .d(e2_p$0$d),
        .q(e2_p$0$q),
        .clock(e2_p$0$clock)
    );
    texture_path$unit$coords$e2_p$1 e2_p$1(
        .d(e2_p$1$d),
        .q(e2_p$1$q),
        .clock(e2_p$1$clock)
    );
    texture_path$unit$coords$e2_idx$0 e2_idx$0(
        .d(e2_idx$0$d),
        .q(e2_idx$0$q),
        .clock(e2_idx$0$clock)
    );
    texture_path$unit$coords$e2_idx$1 e2_idx$1(
        .d(e2_idx$1$d),
        .q(e2_idx$1$q),
        .clock(e2_idx$1$clock)
    );
    texture_path$unit$coords$e2_lz e2_lz(
        .d(e2_lz$d),
        .q(e2_lz$q),
        .clock(e2_lz$clock)
    );
    texture_path$unit$coords$log_m log_m(
        .address(log_m$address),
        .clock(log_m$clock),
        .data(log_m$data)
    );
    texture_path$unit$coords$log_r log_r(
        .address(log_r$address),
        .clock(log_r$clock),
        .data(log_r$data)
    );
    texture_path$unit$coords$e_valid e_valid(
        .d(e_valid$d),
        .q(e_valid$q),
        .clock(e_valid$clock)
    );
    texture_path$unit$coords$e_st$0 e_st$0(
        .d(e_st$0$d),
        .q(e_st$0$q),
        .clock(e_st$0$clock)
    );
    texture_path$unit$coords$e_st$1 e_st$1(
        .d(e_st$1$d),
        .q(e_st$1$q),
        .clock(e_st$1$clock)
    );
    texture_path$unit$coords$e_lambda e_lambda(
        .d(e_lambda$d),
        .q(e_lambda$q),
        .clock(e_lambda$clock)
    );
    
    // Update code
    always @(*) begin
        b1_valid$clock = clock;
        b1_sh$clock = clock;
        b1_lz$clock = clock;
        b1_ws$clock = clock;
        b1_hs$clock = clock;
        b1_r$clock = clock;
        b_valid$clock = clock;
        b_lz$clock = clock;
        b_ws$clock = clock;
        b_hs$clock = clock;
        b_r$clock = clock;
        c1_valid$clock = clock;
        c1_lz$clock = clock;
        c1_ws$clock = clock;
        c1_hs$clock = clock;
        c1_r$clock = clock;
        c_valid$clock = clock;
        c_lz$clock = clock;
        c_r$clock = clock;
        d_valid$clock = clock;
        d_m$clock = clock;
        d_lz$clock = clock;
        d_r$clock = clock;
        e1_valid$clock = clock;
        e1_zero$clock = clock;
        e1_lz$clock = clock;
        e2_valid$clock = clock;
        e2_zero$clock = clock;
        e2_lz$clock = clock;
        e_valid$clock = clock;
        e_lambda$clock = clock;
        b1_valid$d = b1_valid$q;
        b1_sh$d = b1_sh$q;
        b1_lz$d = b1_lz$q;
        b1_ws$d = b1_ws$q;
        b1_hs$d = b1_hs$q;
        b1_r$d = b1_r$q;
        b_valid$d = b_valid$q;
        b_lz$d = b_lz$q;
        b_ws$d = b_ws$q;
        b_hs$d = b_hs$q;
        b_r$d = b_r$q;
        c1_valid$d = c1_valid$q;
        c1_lz$d = c1_lz$q;
        c1_ws$d = c1_ws$q;
        c1_hs$d = c1_hs$q;
        c1_r$d = c1_r$q;
        c_valid$d = c_valid$q;
        c_lz$d = c_lz$q;
        c_r$d = c_r$q;
        d_valid$d = d_valid$q;
        d_m$d = d_m$q;
        d_lz$d = d_lz$q;
        d_r$d = d_r$q;
        e1_valid$d = e1_valid$q;
        e1_zero$d = e1_zero$q;
        e1_lz$d = e1_lz$q;
        e2_valid$d = e2_valid$q;
        e2_zero$d = e2_zero$q;
        e2_lz$d = e2_lz$q;
        e_valid$d = e_valid$q;
        e_lambda$d = e_lambda$q;
        b1_p$0$clock = clock;
        b1_p$0$d = b1_p$0$q;
        b1_dq$0$clock = clock;
        b1_dq$0$d = b1_dq$0$q;
        c1_st$0$clock = clock;
        c1_st$0$d = c1_st$0$q;
        b_st$0$clock = clock;
        b_st$0$d = b_st$0$q;
        b_dq$0$clock = clock;
        b_dq$0$d = b_dq$0$q;
        c_st$0$clock = clock;
        c_st$0$d = c_st$0$q;
        d_st$0$clock = clock;
        d_st$0$d = d_st$0$q;
        e_st$0$clock = clock;
        e_st$0$d = e_st$0$q;
        e1_st$0$clock = clock;
        e1_st$0$d = e1_st$0$q;
        e2_st$0$clock = clock;
        e2_st$0$d = e2_st$0$q;
        e1_p$0$clock = clock;
        e1_p$0$d = e1_p$0$q;
        e2_p$0$clock = clock;
        e2_p$0$d = e2_p$0$q;
        e1_idx$0$clock = clock;
        e1_idx$0$d = e1_idx$0$q;
        e2_idx$0$clock = clock;
        e2_idx$0$d = e2_idx$0$q;
        b1_p$1$clock = clock;
        b1_p$1$d = b1_p$1$q;
        b1_dq$1$clock = clock;
        b1_dq$1$d = b1_dq$1$q;
        c1_st$1$clock = clock;
        c1_st$1$d = c1_st$1$q;
        b_st$1$clock = clock;
        b_st$1$d = b_st$1$q;
        b_dq$1$clock = clock;
        b_dq$1$d = b_dq$1$q;
        c_st$1$clock = clock;
        c_st$1$d = c_st$1$q;
        d_st$1$clock = clock;
        d_st$1$d = d_st$1$q;
        e_st$1$clock = clock;
        e_st$1$d = e_st$1$q;
        e1_st$1$clock = clock;
        e1_st$1$d = e1_st$1$q;
        e2_st$1$clock = clock;
        e2_st$1$d = e2_st$1$q;
        e1_p$1$clock = clock;
        e1_p$1$d = e1_p$1$q;
        e2_p$1$clock = clock;
        e2_p$1$d = e2_p$1$q;
        e1_idx$1$clock = clock;
        e1_idx$1$d = e1_idx$1$q;
        e2_idx$1$clock = clock;
        e2_idx$1$d = e2_idx$1$q;
        b1_dxq$0$clock = clock;
        b1_dxq$0$d = b1_dxq$0$q;
        c1_p$0$clock = clock;
        c1_p$0$d = c1_p$0$q;
        c1_dxq$0$clock = clock;
        c1_dxq$0$d = c1_dxq$0$q;
        b_dxq$0$clock = clock;
        b_dxq$0$d = b_dxq$0$q;
        c_u$0$clock = clock;
        c_u$0$d = c_u$0$q;
        b1_dxq$1$clock = clock;
        b1_dxq$1$d = b1_dxq$1$q;
        c1_p$1$clock = clock;
        c1_p$1$d = c1_p$1$q;
        c1_dxq$1$clock = clock;
        c1_dxq$1$d = c1_dxq$1$q;
        b_dxq$1$clock = clock;
        b_dxq$1$d = b_dxq$1$q;
        c_u$1$clock = clock;
        c_u$1$d = c_u$1$q;
        b1_dxq$2$clock = clock;
        b1_dxq$2$d = b1_dxq$2$q;
        c1_p$2$clock = clock;
        c1_p$2$d = c1_p$2$q;
        c1_dxq$2$clock = clock;
        c1_dxq$2$d = c1_dxq$2$q;
        b_dxq$2$clock = clock;
        b_dxq$2$d = b_dxq$2$q;
        c_u$2$clock = clock;
        c_u$2$d = c_u$2$q;
        b1_dxq$3$clock = clock;
        b1_dxq$3$d = b1_dxq$3$q;
        c1_p$3$clock = clock;
        c1_p$3$d = c1_p$3$q;
        c1_dxq$3$clock = clock;
        c1_dxq$3$d = c1_dxq$3$q;
        b_dxq$3$clock = clock;
        b_dxq$3$d = b_dxq$3$q;
        c_u$3$clock = clock;
        c_u$3$d = c_u$3$q;
        dl_sq$0$clock = clock;
        dl_sq$0$d = dl_sq$0$q;
        dl_tq$0$clock = clock;
        dl_tq$0$d = dl_tq$0$q;
        dl_lz$0$clock = clock;
        dl_lz$0$d = dl_lz$0$q;
        dl_ws$0$clock = clock;
        dl_ws$0$d = dl_ws$0$q;
        dl_hs$0$clock = clock;
        dl_hs$0$d = dl_hs$0$q;
        dl_dsq_x$0$clock = clock;
        dl_dsq_x$0$d = dl_dsq_x$0$q;
        dl_dsq_y$0$clock = clock;
        dl_dsq_y$0$d = dl_dsq_y$0$q;
        dl_dtq_x$0$clock = clock;
        dl_dtq_x$0$d = dl_dtq_x$0$q;
        dl_dtq_y$0$clock = clock;
        dl_dtq_y$0$d = dl_dtq_y$0$q;
        dl_dq_x$0$clock = clock;
        dl_dq_x$0$d = dl_dq_x$0$q;
        dl_dq_y$0$clock = clock;
        dl_dq_y$0$d = dl_dq_y$0$q;
        dl_sq$1$clock = clock;
        dl_sq$1$d = dl_sq$1$q;
        dl_tq$1$clock = clock;
        dl_tq$1$d = dl_tq$1$q;
        dl_lz$1$clock = clock;
        dl_lz$1$d = dl_lz$1$q;
        dl_ws$1$clock = clock;
        dl_ws$1$d = dl_ws$1$q;
        dl_hs$1$clock = clock;
        dl_hs$1$d = dl_hs$1$q;
        dl_dsq_x$1$clock = clock;
        dl_dsq_x$1$d = dl_dsq_x$1$q;
        dl_dsq_y$1$clock = clock;
        dl_dsq_y$1$d = dl_dsq_y$1$q;
        dl_dtq_x$1$clock = clock;
        dl_dtq_x$1$d = dl_dtq_x$1$q;
        dl_dtq_y$1$clock = clock;
        dl_dtq_y$1$d = dl_dtq_y$1$q;
        dl_dq_x$1$clock = clock;
        dl_dq_x$1$d = dl_dq_x$1$q;
        dl_dq_y$1$clock = clock;
        dl_dq_y$1$d = dl_dq_y$1$q;
        dl_sq$2$clock = clock;
        dl_sq$2$d = dl_sq$2$q;
        dl_tq$2$clock = clock;
        dl_tq$2$d = dl_tq$2$q;
        dl_lz$2$clock = clock;
        dl_lz$2$d = dl_lz$2$q;
        dl_ws$2$clock = clock;
        dl_ws$2$d = dl_ws$2$q;
        dl_hs$2$clock = clock;
        dl_hs$2$d = dl_hs$2$q;
        dl_dsq_x$2$clock = clock;
        dl_dsq_x$2$d = dl_dsq_x$2$q;
        dl_dsq_y$2$clock = clock;
        dl_dsq_y$2$d = dl_dsq_y$2$q;
        dl_dtq_x$2$clock = clock;
        dl_dtq_x$2$d = dl_dtq_x$2$q;
        dl_dtq_y$2$clock = clock;
        dl_dtq_y$2$d = dl_dtq_y$2$q;
        dl_dq_x$2$clock = clock;
        dl_dq_x$2$d = dl_dq_x$2$q;
        dl_dq_y$2$clock = clock;
        dl_dq_y$2$d = dl_dq_y$2$q;
        dl_sq$3$clock = clock;
        dl_sq$3$d = dl_sq$3$q;
        dl_tq$3$clock = clock;
        dl_tq$3$d = dl_tq$3$q;
        dl_lz$3$clock = clock;
        dl_lz$3$d = dl_lz$3$q;
        dl_ws$3$clock = clock;
        dl_ws$3$d = dl_ws$3$q;
        dl_hs$3$clock = clock;
        dl_hs$3$d = dl_hs$3$q;
        dl_dsq_x$3$clock = clock;
        dl_dsq_x$3$d = dl_dsq_x$3$q;
        dl_dsq_y$3$clock = clock;
        dl_dsq_y$3$d = dl_dsq_y$3$q;
        dl_dtq_x$3$clock = clock;
        dl_dtq_x$3$d = dl_dtq_x$3$q;
        dl_dtq_y$3$clock = clock;
        dl_dtq_y$3$d = dl_dtq_y$3$q;
        dl_dq_x$3$clock = clock;
        dl_dq_x$3$d = dl_dq_x$3$q;
        dl_dq_y$3$clock = clock;
        dl_dq_y$3$d = dl_dq_y$3$q;
        dl_sq$4$clock = clock;
        dl_sq$4$d = dl_sq$4$q;
        dl_tq$4$clock = clock;
        dl_tq$4$d = dl_tq$4$q;
        dl_lz$4$clock = clock;
        dl_lz$4$d = dl_lz$4$q;
        dl_ws$4$clock = clock;
        dl_ws$4$d = dl_ws$4$q;
        dl_hs$4$clock = clock;
        dl_hs$4$d = dl_hs$4$q;
        dl_dsq_x$4$clock = clock;
        dl_dsq_x$4$d = dl_dsq_x$4$q;
        dl_dsq_y$4$clock = clock;
        dl_dsq_y$4$d = dl_dsq_y$4$q;
        dl_dtq_x$4$clock = clock;
        dl_dtq_x$4$d = dl_dtq_x$4$q;
        dl_dtq_y$4$clock = clock;
        dl_dtq_y$4$d = dl_dtq_y$4$q;
        dl_dq_x$4$clock = clock;
        dl_dq_x$4$d = dl_dq_x$4$q;
        dl_dq_y$4$clock = clock;
        dl_dq_y$4$d = dl_dq_y$4$q;
        dl_sq$5$clock = clock;
        dl_sq$5$d = dl_sq$5$q;
        dl_tq$5$clock = clock;
        dl_tq$5$d = dl_tq$5$q;
        dl_lz$5$clock = clock;
        dl_lz$5$d = dl_lz$5$q;
        dl_ws$5$clock = clock;
        dl_ws$5$d = dl_ws$5$q;
        dl_hs$5$clock = clock;
        dl_hs$5$d = dl_hs$5$q;
        dl_dsq_x$5$clock = clock;
        dl_dsq_x$5$d = dl_dsq_x$5$q;
        dl_dsq_y$5$clock = clock;
        dl_dsq_y$5$d = dl_dsq_y$5$q;
        dl_dtq_x$5$clock = clock;
        dl_dtq_x$5$d = dl_dtq_x$5$q;
        dl_dtq_y$5$clock = clock;
        dl_dtq_y$5$d = dl_dtq_y$5$q;
        dl_dq_x$5$clock = clock;
        dl_dq_x$5$d = dl_dq_x$5$q;
        dl_dq_y$5$clock = clock;
        dl_dq_y$5$d = dl_dq_y$5$q;
        dl_sq$6$clock = clock;
        dl_sq$6$d = dl_sq$6$q;
        dl_tq$6$clock = clock;
        dl_tq$6$d = dl_tq$6$q;
        dl_lz$6$clock = clock;
        dl_lz$6$d = dl_lz$6$q;
        dl_ws$6$clock = clock;
        dl_ws$6$d = dl_ws$6$q;
        dl_hs$6$clock = clock;
        dl_hs$6$d = dl_hs$6$q;
        dl_dsq_x$6$clock = clock;
        dl_dsq_x$6$d = dl_dsq_x$6$q;
        dl_dsq_y$6$clock = clock;
        dl_dsq_y$6$d = dl_dsq_y$6$q;
        dl_dtq_x$6$clock = clock;
        dl_dtq_x$6$d = dl_dtq_x$6$q;
        dl_dtq_y$6$clock = clock;
        dl_dtq_y$6$d = dl_dtq_y$6$q;
        dl_dq_x$6$clock = clock;
        dl_dq_x$6$d = dl_dq_x$6$q;
        dl_dq_y$6$clock = clock;
        dl_dq_y$6$d = dl_dq_y$6$q;
        dl_sq$7$clock = clock;
        dl_sq$7$d = dl_sq$7$q;
        dl_tq$7$clock = clock;
        dl_tq$7$d = dl_tq$7$q;
        dl_lz$7$clock = clock;
        dl_lz$7$d = dl_lz$7$q;
        dl_ws$7$clock = clock;
        dl_ws$7$d = dl_ws$7$q;
        dl_hs$7$clock = clock;
        dl_hs$7$d = dl_hs$7$q;
        dl_dsq_x$7$clock = clock;
        dl_dsq_x$7$d = dl_dsq_x$7$q;
        dl_dsq_y$7$clock = clock;
        dl_dsq_y$7$d = dl_dsq_y$7$q;
        dl_dtq_x$7$clock = clock;
        dl_dtq_x$7$d = dl_dtq_x$7$q;
        dl_dtq_y$7$clock = clock;
        dl_dtq_y$7$d = dl_dtq_y$7$q;
        dl_dq_x$7$clock = clock;
        dl_dq_x$7$d = dl_dq_x$7$q;
        dl_dq_y$7$clock = clock;
        dl_dq_y$7$d = dl_dq_y$7$q;
        dl_sq$8$clock = clock;
        dl_sq$8$d = dl_sq$8$q;
        dl_tq$8$clock = clock;
        dl_tq$8$d = dl_tq$8$q;
        dl_lz$8$clock = clock;
        dl_lz$8$d = dl_lz$8$q;
        dl_ws$8$clock = clock;
        dl_ws$8$d = dl_ws$8$q;
        dl_hs$8$clock = clock;
        dl_hs$8$d = dl_hs$8$q;
        dl_dsq_x$8$clock = clock;
        dl_dsq_x$8$d = dl_dsq_x$8$q;
        dl_dsq_y$8$clock = clock;
        dl_dsq_y$8$d = dl_dsq_y$8$q;
        dl_dtq_x$8$clock = clock;
        dl_dtq_x$8$d = dl_dtq_x$8$q;
        dl_dtq_y$8$clock = clock;
        dl_dtq_y$8$d = dl_dtq_y$8$q;
        dl_dq_x$8$clock = clock;
        dl_dq_x$8$d = dl_dq_x$8$q;
        dl_dq_y$8$clock = clock;
        dl_dq_y$8$d = dl_dq_y$8$q;
        dl_sq$9$clock = clock;
        dl_sq$9$d = dl_sq$9$q;
        dl_tq$9$clock = clock;
        dl_tq$9$d = dl_tq$9$q;
        dl_lz$9$clock = clock;
        dl_lz$9$d = dl_lz$9$q;
        dl_ws$9$clock = clock;
        dl_ws$9$d = dl_ws$9$q;
        dl_hs$9$clock = clock;
        dl_hs$9$d = dl_hs$9$q;
        dl_dsq_x$9$clock = clock;
        dl_dsq_x$9$d = dl_dsq_x$9$q;
        dl_dsq_y$9$clock = clock;
        dl_dsq_y$9$d = dl_dsq_y$9$q;
        dl_dtq_x$9$clock = clock;
        dl_dtq_x$9$d = dl_dtq_x$9$q;
        dl_dtq_y$9$clock = clock;
        dl_dtq_y$9$d = dl_dtq_y$9$q;
        dl_dq_x$9$clock = clock;
        dl_dq_x$9$d = dl_dq_x$9$q;
        dl_dq_y$9$clock = clock;
        dl_dq_y$9$d = dl_dq_y$9$q;
        dl_sq$10$clock = clock;
        dl_sq$10$d = dl_sq$10$q;
        dl_tq$10$clock = clock;
        dl_tq$10$d = dl_tq$10$q;
        dl_lz$10$clock = clock;
        dl_lz$10$d = dl_lz$10$q;
        dl_ws$10$clock = clock;
        dl_ws$10$d = dl_ws$10$q;
        dl_hs$10$clock = clock;
        dl_hs$10$d = dl_hs$10$q;
        dl_dsq_x$10$clock = clock;
        dl_dsq_x$10$d = dl_dsq_x$10$q;
        dl_dsq_y$10$clock = clock;
        dl_dsq_y$10$d = dl_dsq_y$10$q;
        dl_dtq_x$10$clock = clock;
        dl_dtq_x$10$d = dl_dtq_x$10$q;
        dl_dtq_y$10$clock = clock;
        dl_dtq_y$10$d = dl_dtq_y$10$q;
        dl_dq_x$10$clock = clock;
        dl_dq_x$10$d = dl_dq_x$10$q;
        dl_dq_y$10$clock = clock;
        dl_dq_y$10$d = dl_dq_y$10$q;
        dl_sq$11$clock = clock;
        dl_sq$11$d = dl_sq$11$q;
        dl_tq$11$clock = clock;
        dl_tq$11$d = dl_tq$11$q;
        dl_lz$11$clock = clock;
        dl_lz$11$d = dl_lz$11$q;
        dl_ws$11$clock = clock;
        dl_ws$11$d = dl_ws$11$q;
        dl_hs$11$clock = clock;
        dl_hs$11$d = dl_hs$11$q;
        dl_dsq_x$11$clock = clock;
        dl_dsq_x$11$d = dl_dsq_x$11$q;
        dl_dsq_y$11$clock = clock;
        dl_dsq_y$11$d = dl_dsq_y$11$q;
        dl_dtq_x$11$clock = clock;
        dl_dtq_x$11$d = dl_dtq_x$11$q;
        dl_dtq_y$11$clock = clock;
        dl_dtq_y$11$d = dl_dtq_y$11$q;
        dl_dq_x$11$clock = clock;
        dl_dq_x$11$d = dl_dq_x$11$q;
        dl_dq_y$11$clock = clock;
        dl_dq_y$11$d = dl_dq_y$11$q;
        dl_sq$12$clock = clock;
        dl_sq$12$d = dl_sq$12$q;
        dl_tq$12$clock = clock;
        dl_tq$12$d = dl_tq$12$q;
        dl_lz$12$clock = clock;
        dl_lz$12$d = dl_lz$12$q;
        dl_ws$12$clock = clock;
        dl_ws$12$d = dl_ws$12$q;
        dl_hs$12$clock = clock;
        dl_hs$12$d = dl_hs$12$q;
        dl_dsq_x$12$clock = clock;
        dl_dsq_x$12$d = dl_dsq_x$12$q;
        dl_dsq_y$12$clock = clock;
        dl_dsq_y$12$d = dl_dsq_y$12$q;
        dl_dtq_x$12$clock = clock;
        dl_dtq_x$12$d = dl_dtq_x$12$q;
        dl_dtq_y$12$clock = clock;
        dl_dtq_y$12$d = dl_dtq_y$12$q;
        dl_dq_x$12$clock = clock;
        dl_dq_x$12$d = dl_dq_x$12$q;
        dl_dq_y$12$clock = clock;
        dl_dq_y$12$d = dl_dq_y$12$q;
        qn = inp_q;
        if (~|inp_q) begin
            qn = 32'h1;
        end
        lz = 32'h0;
        if (qn[0]) begin
            lz = qb_top - index$0;
        end
        if (qn[1]) begin
            lz = qb_top - index$1;
        end
        if (qn[2]) begin
            lz = qb_top - index$2;
        end
        if (qn[3]) begin
            lz = qb_top - index$3;
        end
        if (qn[4]) begin
            lz = qb_top - index$4;
        end
        if (qn[5]) begin
            lz = qb_top - index$5;
        end
        if (qn[6]) begin
            lz = qb_top - index$6;
        end
        if (qn[7]) begin
            lz = qb_top - index$7;
        end
        if (qn[8]) begin
            lz = qb_top - index$8;
        end
        if (qn[9]) begin
            lz = qb_top - index$9;
        end
        if (qn[10]) begin
            lz = qb_top - index$10;
        end
        if (qn[11]) begin
            lz = qb_top - index$11;
        end
        if (qn[12]) begin
            lz = qb_top - index$12;
        end
        if (qn[13]) begin
            lz = qb_top - index$13;
        end
        if (qn[14]) begin
            lz = qb_top - index$14;
        end
        if (qn[15]) begin
            lz = qb_top - index$15;
        end
        if (qn[16]) begin
            lz = qb_top - index$16;
        end
        if (qn[17]) begin
            lz = qb_top - index$17;
        end
        if (qn[18]) begin
            lz = qb_top - index$18;
        end
        if (qn[19]) begin
            lz = qb_top - index$19;
        end
        if (qn[20]) begin
            lz = qb_top - index$20;
        end
        recip$clock = clock;
        recip$hold = ~en;
        recip$out_ready = 1'b1;
        recip$inp_valid = inp_valid;
        recip$inp_n = dividend;
        recip$inp_d = qn << ((lz) & 21'h1fffff);
        if (en) begin
            dl_sq$0$d = inp_sq;
            dl_tq$0$d = inp_tq;
            dl_dsq_x$0$d = inp_dsq_x;
            dl_dsq_y$0$d = inp_dsq_y;
            dl_dtq_x$0$d = inp_dtq_x;
            dl_dtq_y$0$d = inp_dtq_y;
            dl_dq_x$0$d = inp_dq_x;
            dl_dq_y$0$d = inp_dq_y;
            dl_lz$0$d = lz;
            dl_ws$0$d = inp_ws;
            dl_hs$0$d = inp_hs;
            dl_sq$1$d = dl_sq$0$q;
            dl_tq$1$d = dl_tq$0$q;
            dl_lz$1$d = dl_lz$0$q;
            dl_ws$1$d = dl_ws$0$q;
            dl_hs$1$d = dl_hs$0$q;
            dl_dsq_x$1$d = dl_dsq_x$0$q;
            dl_dsq_y$1$d = dl_dsq_y$0$q;
            dl_dtq_x$1$d = dl_dtq_x$0$q;
            dl_dtq_y$1$d = dl_dtq_y$0$q;
            dl_dq_x$1$d = dl_dq_x$0$q;
            dl_dq_y$1$d = dl_dq_y$0$q;
            dl_sq$2$d = dl_sq$1$q;
            dl_tq$2$d = dl_tq$1$q;
            dl_lz$2$d = dl_lz$1$q;
            dl_ws$2$d = dl_ws$1$q;
            dl_hs$2$d = dl_hs$1$q;
            dl_dsq_x$2$d = dl_dsq_x$1$q;
            dl_dsq_y$2$d = dl_dsq_y$1$q;
            dl_dtq_x$2$d = dl_dtq_x$1$q;
            dl_dtq_y$2$d = dl_dtq_y$1$q;
            dl_dq_x$2$d = dl_dq_x$1$q;
            dl_dq_y$2$d = dl_dq_y$1$q;
            dl_sq$3$d = dl_sq$2$q;
            dl_tq$3$d = dl_tq$2$q;
            dl_lz$3$d = dl_lz$2$q;
            dl_ws$3$d = dl_ws$2$q;
            dl_hs$3$d = dl_hs$2$q;
            dl_dsq_x$3$d = dl_dsq_x$2$q;
            dl_dsq_y$3$d = dl_dsq_y$2$q;
            dl_dtq_x$3$d = dl_dtq_x$2$q;
            dl_dtq_y$3$d = dl_dtq_y$2$q;
            dl_dq_x$3$d = dl_dq_x$2$q;
            dl_dq_y$3$d = dl_dq_y$2$q;
            dl_sq$4$d = dl_sq$3$q;
            dl_tq$4$d = dl_tq$3$q;
            dl_lz$4$d = dl_lz$3$q;
            dl_ws$4$d = dl_ws$3$q;
            dl_hs$4$d = dl_hs$3$q;
            dl_dsq_x$4$d = dl_dsq_x$3$q;
            dl_dsq_y$4$d = dl_dsq_y$3$q;
            dl_dtq_x$4$d = dl_dtq_x$3$q;
            dl_dtq_y$4$d = dl_dtq_y$3$q;
            dl_dq_x$4$d = dl_dq_x$3$q;
            dl_dq_y$4$d = dl_dq_y$3$q;
            dl_sq$5$d = dl_sq$4$q;
            dl_tq$5$d = dl_tq$4$q;
            dl_lz$5$d = dl_lz$4$q;
            dl_ws$5$d = dl_ws$4$q;
            dl_hs$5$d = dl_hs$4$q;
            dl_dsq_x$5$d = dl_dsq_x$4$q;
            dl_dsq_y$5$d = dl_dsq_y$4$q;
            dl_dtq_x$5$d = dl_dtq_x$4$q;
            dl_dtq_y$5$d = dl_dtq_y$4$q;
            dl_dq_x$5$d = dl_dq_x$4$q;
            dl_dq_y$5$d = dl_dq_y$4$q;
            dl_sq$6$d = dl_sq$5$q;
            dl_tq$6$d = dl_tq$5$q;
            dl_lz$6$d = dl_lz$5$q;
            dl_ws$6$d = dl_ws$5$q;
            dl_hs$6$d = dl_hs$5$q;
            dl_dsq_x$6$d = dl_dsq_x$5$q;
            dl_dsq_y$6$d = dl_dsq_y$5$q;
            dl_dtq_x$6$d = dl_dtq_x$5$q;
            dl_dtq_y$6$d = dl_dtq_y$5$q;
            dl_dq_x$6$d = dl_dq_x$5$q;
            dl_dq_y$6$d = dl_dq_y$5$q;
            dl_sq$7$d = dl_sq$6$q;
            dl_tq$7$d = dl_tq$6$q;
            dl_lz$7$d = dl_lz$6$q;
            dl_ws$7$d = dl_ws$6$q;
            dl_hs$7$d = dl_hs$6$q;
            dl_dsq_x$7$d = dl_dsq_x$6$q;
            dl_dsq_y$7$d = dl_dsq_y$6$q;
            dl_dtq_x$7$d = dl_dtq_x$6$q;
            dl_dtq_y$7$d = dl_dtq_y$6$q;
            dl_dq_x$7$d = dl_dq_x$6$q;
            dl_dq_y$7$d = dl_dq_y$6$q;
            dl_sq$8$d = dl_sq$7$q;
            dl_tq$8$d = dl_tq$7$q;
            dl_lz$8$d = dl_lz$7$q;
            dl_ws$8$d = dl_ws$7$q;
            dl_hs$8$d = dl_hs$7$q;
            dl_dsq_x$8$d = dl_dsq_x$7$q;
            dl_dsq_y$8$d = dl_dsq_y$7$q;
            dl_dtq_x$8$d = dl_dtq_x$7$q;
            dl_dtq_y$8$d = dl_dtq_y$7$q;
            dl_dq_x$8$d = dl_dq_x$7$q;
            dl_dq_y$8$d = dl_dq_y$7$q;
            dl_sq$9$d = dl_sq$8$q;
            dl_tq$9$d = dl_tq$8$q;
            dl_lz$9$d = dl_lz$8$q;
            dl_ws$9$d = dl_ws$8$q;
            dl_hs$9$d = dl_hs$8$q;
            dl_dsq_x$9$d = dl_dsq_x$8$q;
            dl_dsq_y$9$d = dl_dsq_y$8$q;
            dl_dtq_x$9$d = dl_dtq_x$8$q;
            dl_dtq_y$9$d = dl_dtq_y$8$q;
            dl_dq_x$9$d = dl_dq_x$8$q;
            dl_dq_y$9$d = dl_dq_y$8$q;
            dl_sq$10$d = dl_sq$9$q;
            dl_tq$10$d = dl_tq$9$q;
            dl_lz$10$d = dl_lz$9$q;
            dl_ws$10$d = dl_ws$9$q;
            dl_hs$10$d = dl_hs$9$q;
            dl_dsq_x$10$d = dl_dsq_x$9$q;
            dl_dsq_y$10$d = dl_dsq_y$9$q;
            dl_dtq_x$10$d = dl_dtq_x$9$q;
            dl_dtq_y$10$d = dl_dtq_y$9$q;
            dl_dq_x$10$d = dl_dq_x$9$q;
            dl_dq_y$10$d = dl_dq_y$9$q;
            dl_sq$11$d = dl_sq$10$q;
            dl_tq$11$d = dl_tq$10$q;
            dl_lz$11$d = dl_lz$10$q;
            dl_ws$11$d = dl_ws$10$q;
            dl_hs$11$d = dl_hs$10$q;
            dl_dsq_x$11$d = dl_dsq_x$10$q;
            dl_dsq_y$11$d = dl_dsq_y$10$q;
            dl_dtq_x$11$d = dl_dtq_x$10$q;
            dl_dtq_y$11$d = dl_dtq_y$10$q;
            dl_dq_x$11$d = dl_dq_x$10$q;
            dl_dq_y$11$d = dl_dq_y$10$q;
            dl_sq$12$d = dl_sq$11$q;
            dl_tq$12$d = dl_tq$11$q;
            dl_lz$12$d = dl_lz$11$q;
            dl_ws$12$d = dl_ws$11$q;
            dl_hs$12$d = dl_hs$11$q;
            dl_dsq_x$12$d = dl_dsq_x$11$q;
            dl_dsq_y$12$d = dl_dsq_y$11$q;
            dl_dtq_x$12$d = dl_dtq_x$11$q;
            dl_dtq_y$12$d = dl_dtq_y$11$q;
            dl_dq_x$12$d = dl_dq_x$11$q;
            dl_dq_y$12$d = dl_dq_y$11$q;
        end
        mul_s$a = dl_sq$12$q;
        mul_t$a = dl_tq$12$q;
        sh = recip_1 - dl_lz$12$q;
        mul_s$b = recip$out_q;
        mul_t$b = recip$out_q;
        if (en) begin
            b1_valid$d = recip$out_valid;
            b1_r$d = recip$out_q;
            b1_p$0$d = mul_s$p;
            b1_p$1$d = mul_t$p;
            b1_sh$d = sh;
            b1_dxq$0$d = dl_dsq_x$12$q;
            b1_dxq$1$d = dl_dsq_y$12$q;
            b1_dxq$2$d = dl_dtq_x$12$q;
            b1_dxq$3$d = dl_dtq_y$12$q;
            b1_dq$0$d = dl_dq_x$12$q;
            b1_dq$1$d = dl_dq_y$12$q;
            b1_lz$d = dl_lz$12$q;
            b1_ws$d = dl_ws$12$q;
            b1_hs$d = dl_hs$12$q;
        end
        wide$0 = b1_p$0$q >> b1_sh$q;
        if (b1_p$0$q[ps_msb]) begin
            wide$0 = (b1_p$0$q >> b1_sh$q) | ~(ones_ps >> b1_sh$q);
        end
        wide$1 = b1_p$1$q >> b1_sh$q;
        if (b1_p$1$q[ps_msb]) begin
            wide$1 = (b1_p$1$q >> b1_sh$q) | ~(ones_ps >> b1_sh$q);
        end
        st_c$0 = wide$0[(32'h0)+:(29)];
        if (|(wide$0 >> st_msb) & ~(&wide$0[(st_msb)+:(28)])) begin
            st_c$0 = st_max;
            if (wide$0[ps_msb]) begin
                st_c$0 = st_min;
            end
        end
        st_c$1 = wide$1[(32'h0)+:(29)];
        if (|(wide$1 >> st_msb) & ~(&wide$1[(st_msb)+:(28)])) begin
            st_c$1 = st_max;
            if (wide$1[ps_msb]) begin
                st_c$1 = st_min;
            end
        end
        if (en) begin
            b_valid$d = b1_valid$q;
            b_r$d = b1_r$q;
            b_st$0$d = st_c$0;
            b_dq$0$d = b1_dq$0$q;
            b_st$1$d = st_c$1;
            b_dq$1$d = b1_dq$1$q;
            b_dxq$0$d = b1_dxq$0$q;
            b_dxq$1$d = b1_dxq$1$q;
            b_dxq$2$d = b1_dxq$2$q;
            b_dxq$3$d = b1_dxq$3$q;
            b_lz$d = b1_lz$q;
            b_ws$d = b1_ws$q;
            b_hs$d = b1_hs$q;
        end
        mul_g$0$a = b_st$0$q;
        mul_g$0$b = b_dq$0$q;
        mul_g$1$a = b_st$0$q;
        mul_g$1$b = b_dq$1$q;
        mul_g$2$a = b_st$1$q;
        mul_g$2$b = b_dq$0$q;
        mul_g$3$a = b_st$1$q;
        mul_g$3$b = b_dq$1$q;
        if (en) begin
            c1_valid$d = b_valid$q;
            c1_st$0$d = b_st$0$q;
            c1_st$1$d = b_st$1$q;
            c1_p$0$d = mul_g$0$p[(g_shift)+:(35)];
            c1_dxq$0$d = b_dxq$0$q;
            c1_p$1$d = mul_g$1$p[(g_shift)+:(35)];
            c1_dxq$1$d = b_dxq$1$q;
            c1_p$2$d = mul_g$2$p[(g_shift)+:(35)];
            c1_dxq$2$d = b_dxq$2$q;
            c1_p$3$d = mul_g$3$p[(g_shift)+:(35)];
            c1_dxq$3$d = b_dxq$3$q;
            c1_lz$d = b_lz$q;
            c1_ws$d = b_ws$q;
            c1_hs$d = b_hs$q;
            c1_r$d = b_r$q;
        end
        num$0$size_log2 = c1_ws$q;
        num$1$size_log2 = c1_ws$q;
        num$2$size_log2 = c1_hs$q;
        num$3$size_log2 = c1_hs$q;
        num$0$dxq = c1_dxq$0$q;
        num$0$p = c1_p$0$q;
        num$1$dxq = c1_dxq$1$q;
        num$1$p = c1_p$1$q;
        num$2$dxq = c1_dxq$2$q;
        num$2$p = c1_p$2$q;
        num$3$dxq = c1_dxq$3$q;
        num$3$p = c1_p$3$q;
        if (en) begin
            c_valid$d = c1_valid$q;
            c_st$0$d = c1_st$0$q;
            c_st$1$d = c1_st$1$q;
            c_u$0$d = num$0$u;
            c_u$1$d = num$1$u;
            c_u$2$d = num$2$u;
            c_u$3$d = num$3$u;
            c_lz$d = c1_lz$q;
            c_r$d = c1_r$q;
        end
        m_01 = c_u$0$q;
        if (c_u$1$q > c_u$0$q) begin
            m_01 = c_u$1$q;
        end
        m_23 = c_u$2$q;
        if (c_u$3$q > c_u$2$q) begin
            m_23 = c_u$3$q;
        end
        m_max = m_01;
        if (m_23 > m_01) begin
            m_max = m_23;
        end
        mul_sq$0$a = ((c_u$0$q) & 48'hffffffffffff);
        mul_sq$0$b = ((c_u$0$q) & 48'hffffffffffff);
        mul_sq$1$a = ((c_u$1$q) & 48'hffffffffffff);
        mul_sq$1$b = ((c_u$1$q) & 48'hffffffffffff);
        mul_sq$2$a = ((c_u$2$q) & 48'hffffffffffff);
        mul_sq$2$b = ((c_u$2$q) & 48'hffffffffffff);
        mul_sq$3$a = ((c_u$3$q) & 48'hffffffffffff);
        mul_sq$3$b = ((c_u$3$q) & 48'hffffffffffff);
        m_x = ((mul_sq$0$p) & 95'h7fffffffffffffffffffffff) + ((mul_sq$2$p) & 95'h7fffffffffffffffffffffff);
        m_y = ((mul_sq$1$p) & 95'h7fffffffffffffffffffffff) + ((mul_sq$3$p) & 95'h7fffffffffffffffffffffff);
        if (en) begin
            d_valid$d = c_valid$q;
            d_st$0$d = c_st$0$q;
            d_st$1$d = c_st$1$q;
            d_m$d = ((m_max) & 95'h7fffffffffffffffffffffff);
            if (exact) begin
                d_m$d = m_x;
                if (m_y > m_x) begin
                    d_m$d = m_y;
                end
            end
            d_lz$d = c_lz$q;
            d_r$d = c_r$q;
        end
        p_m = 32'h0;
        if (d_m$q[0]) begin
            p_m = index$0;
        end
        if (d_m$q[1]) begin
            p_m = index$1;
        end
        if (d_m$q[2]) begin
            p_m = index$2;
        end
        if (d_m$q[3]) begin
            p_m = index$3;
        end
        if (d_m$q[4]) begin
            p_m = index$4;
        end
        if (d_m$q[5]) begin
            p_m = index$5;
        end
        if (d_m$q[6]) begin
            p_m = index$6;
        end
        if (d_m$q[7]) begin
            p_m = index$7;
        end
        if (d_m$q[8]) begin
            p_m = index$8;
        end
        if (d_m$q[9]) begin
            p_m = index$9;
        end
        if (d_m$q[10]) begin
            p_m = index$10;
        end
        if (d_m$q[11]) begin
            p_m = index$11;
        end
        if (d_m$q[12]) begin
            p_m = index$12;
        end
        if (d_m$q[13]) begin
            p_m = index$13;
        end
        if (d_m$q[14]) begin
            p_m = index$14;
        end
        if (d_m$q[15]) begin
            p_m = index$15;
        end
        if (d_m$q[16]) begin
            p_m = index$16;
        end
        if (d_m$q[17]) begin
            p_m = index$17;
        end
        if (d_m$q[18]) begin
            p_m = index$18;
        end
        if (d_m$q[19]) begin
            p_m = index$19;
        end
        if (d_m$q[20]) begin
            p_m = index$20;
        end
        if (d_m$q[21]) begin
            p_m = index$21;
        end
        if (d_m$q[22]) begin
            p_m = index$22;
        end
        if (d_m$q[23]) begin
            p_m = index$23;
        end
        if (d_m$q[24]) begin
            p_m = index$24;
        end
        if (d_m$q[25]) begin
            p_m = index$25;
        end
        if (d_m$q[26]) begin
            p_m = index$26;
        end
        if (d_m$q[27]) begin
            p_m = index$27;
        end
        if (d_m$q[28]) begin
            p_m = index$28;
        end
        if (d_m$q[29]) begin
            p_m = index$29;
        end
        if (d_m$q[30]) begin
            p_m = index$30;
        end
        if (d_m$q[31]) begin
            p_m = index$31;
        end
        if (d_m$q[32]) begin
            p_m = index$32;
        end
        if (d_m$q[33]) begin
            p_m = index$33;
        end
        if (d_m$q[34]) begin
            p_m = index$34;
        end
        if (d_m$q[35]) begin
            p_m = index$35;
        end
        if (d_m$q[36]) begin
            p_m = index$36;
        end
        if (d_m$q[37]) begin
            p_m = index$37;
        end
        if (d_m$q[38]) begin
            p_m = index$38;
        end
        if (d_m$q[39]) begin
            p_m = index$39;
        end
        if (d_m$q[40]) begin
            p_m = index$40;
        end
        if (d_m$q[41]) begin
            p_m = index$41;
        end
        if (d_m$q[42]) begin
            p_m = index$42;
        end
        if (d_m$q[43]) begin
            p_m = index$43;
        end
        if (d_m$q[44]) begin
            p_m = index$44;
        end
        if (d_m$q[45]) begin
            p_m = index$45;
        end
        if (d_m$q[46]) begin
            p_m = index$46;
        end
        if (d_m$q[47]) begin
            p_m = index$47;
        end
        if (d_m$q[48]) begin
            p_m = index$48;
        end
        if (d_m$q[49]) begin
            p_m = index$49;
        end
        if (d_m$q[50]) begin
            p_m = index$50;
        end
        if (d_m$q[51]) begin
            p_m = index$51;
        end
        if (d_m$q[52]) begin
            p_m = index$52;
        end
        if (d_m$q[53]) begin
            p_m = index$53;
        end
        if (d_m$q[54]) begin
            p_m = index$54;
        end
        if (d_m$q[55]) begin
            p_m = index$55;
        end
        if (d_m$q[56]) begin
            p_m = index$56;
        end
        if (d_m$q[57]) begin
            p_m = index$57;
        end
        if (d_m$q[58]) begin
            p_m = index$58;
        end
        if (d_m$q[59]) begin
            p_m = index$59;
        end
        if (d_m$q[60]) begin
            p_m = index$60;
        end
        if (d_m$q[61]) begin
            p_m = index$61;
        end
        if (d_m$q[62]) begin
            p_m = index$62;
        end
        if (d_m$q[63]) begin
            p_m = index$63;
        end
        if (d_m$q[64]) begin
            p_m = index$64;
        end
        if (d_m$q[65]) begin
            p_m = index$65;
        end
        if (d_m$q[66]) begin
            p_m = index$66;
        end
        if (d_m$q[67]) begin
            p_m = index$67;
        end
        if (d_m$q[68]) begin
            p_m = index$68;
        end
        if (d_m$q[69]) begin
            p_m = index$69;
        end
        if (d_m$q[70]) begin
            p_m = index$70;
        end
        if (d_m$q[71]) begin
            p_m = index$71;
        end
        if (d_m$q[72]) begin
            p_m = index$72;
        end
        if (d_m$q[73]) begin
            p_m = index$73;
        end
        if (d_m$q[74]) begin
            p_m = index$74;
        end
        if (d_m$q[75]) begin
            p_m = index$75;
        end
        if (d_m$q[76]) begin
            p_m = index$76;
        end
        if (d_m$q[77]) begin
            p_m = index$77;
        end
        if (d_m$q[78]) begin
            p_m = index$78;
        end
        if (d_m$q[79]) begin
            p_m = index$79;
        end
        if (d_m$q[80]) begin
            p_m = index$80;
        end
        if (d_m$q[81]) begin
            p_m = index$81;
        end
        if (d_m$q[82]) begin
            p_m = index$82;
        end
        if (d_m$q[83]) begin
            p_m = index$83;
        end
        if (d_m$q[84]) begin
            p_m = index$84;
        end
        if (d_m$q[85]) begin
            p_m = index$85;
        end
        if (d_m$q[86]) begin
            p_m = index$86;
        end
        if (d_m$q[87]) begin
            p_m = index$87;
        end
        if (d_m$q[88]) begin
            p_m = index$88;
        end
        if (d_m$q[89]) begin
            p_m = index$89;
        end
        if (d_m$q[90]) begin
            p_m = index$90;
        end
        if (d_m$q[91]) begin
            p_m = index$91;
        end
        if (d_m$q[92]) begin
            p_m = index$92;
        end
        if (d_m$q[93]) begin
            p_m = index$93;
        end
        if (d_m$q[94]) begin
            p_m = index$94;
        end
        p_r = 32'h0;
        if (d_r$q[0]) begin
            p_r = index$0;
        end
        if (d_r$q[1]) begin
            p_r = index$1;
        end
        if (d_r$q[2]) begin
            p_r = index$2;
        end
        if (d_r$q[3]) begin
            p_r = index$3;
        end
        if (d_r$q[4]) begin
            p_r = index$4;
        end
        if (d_r$q[5]) begin
            p_r = index$5;
        end
        if (d_r$q[6]) begin
            p_r = index$6;
        end
        if (d_r$q[7]) begin
            p_r = index$7;
        end
        if (d_r$q[8]) begin
            p_r = index$8;
        end
        if (d_r$q[9]) begin
            p_r = index$9;
        end
        if (d_r$q[10]) begin
            p_r = index$10;
        end
        if (d_r$q[11]) begin
            p_r = index$11;
        end
        if (d_r$q[12]) begin
            p_r = index$12;
        end
        if (d_r$q[13]) begin
            p_r = index$13;
        end
        if (d_r$q[14]) begin
            p_r = index$14;
        end
        if (d_r$q[15]) begin
            p_r = index$15;
        end
        if (d_r$q[16]) begin
            p_r = index$16;
        end
        if (d_r$q[17]) begin
            p_r = index$17;
        end
        if (d_r$q[18]) begin
            p_r = index$18;
        end
        if (d_r$q[19]) begin
            p_r = index$19;
        end
        if (d_r$q[20]) begin
            p_r = index$20;
        end
        if (d_r$q[21]) begin
            p_r = index$21;
        end
        if (d_r$q[22]) begin
            p_r = index$22;
        end
        if (d_r$q[23]) begin
            p_r = index$23;
        end
        if (d_r$q[24]) begin
            p_r = index$24;
        end
        if (d_r$q[25]) begin
            p_r = index$25;
        end
        if (d_r$q[26]) begin
            p_r = index$26;
        end
        norm_m = d_m$q << (m_top - p_m);
        norm_r = d_r$q << (r_top - p_r);
        if (en) begin
            e1_valid$d = d_valid$q;
            e1_zero$d = ~|d_m$q;
            e1_p$0$d = p_m;
            e1_p$1$d = p_r;
            e1_idx$0$d = norm_m[(m_index)+:(10)];
            e1_idx$1$d = norm_r[(r_index)+:(10)];
            e1_lz$d = d_lz$q;
            e2_valid$d = e1_valid$q;
            e2_zero$d = e1_zero$q;
            e2_lz$d = e1_lz$q;
            e1_st$0$d = d_st$0$q;
            e2_st$0$d = e1_st$0$q;
            e2_p$0$d = e1_p$0$q;
            e2_idx$0$d = e1_idx$0$q;
            e1_st$1$d = d_st$1$q;
            e2_st$1$d = e1_st$1$q;
            e2_p$1$d = e1_p$1$q;
            e2_idx$1$d = e1_idx$1$q;
        end
        log_m$clock = clock;
        log_r$clock = clock;
        log_m$address = e2_idx$0$q;
        log_r$address = e2_idx$1$q;
        if (en) begin
            log_m$address = e1_idx$0$q;
            log_r$address = e1_idx$1$q;
        end
        sum = (((e2_p$0$q) & 24'hffffff) << t_bits) + (((log_m$data) & 24'hffffff) << 32'h1);
        if (exact) begin
            sum = (((e2_p$0$q) & 24'hffffff) << t_less_1) + ((log_m$data) & 24'hffffff);
        end
        rounded = sum + (((e2_p$1$q) & 24'hffffff) << t_bits) + (((log_r$data) & 24'hffffff) << 32'h1) + offset + (((e2_lz$q) & 24'hffffff) << t_bits) + 32'h8;
        lambda24 = rounded >> 32'h4;
        if (rounded[sum_msb]) begin
            lambda24 = (rounded >> 32'h4) | ~(ones_sum >> 32'h4);
        end
        if (en) begin
            e_valid$d = e2_valid$q;
            e_st$0$d = e2_st$0$q;
            e_st$1$d = e2_st$1$q;
            e_lambda$d = ((lambda24) & 32'hffffffff);
            if (lambda24[sum_msb]) begin
                e_lambda$d = ((lambda24) & 32'hffffffff) | ext_lambda;
            end
            if (e2_zero$q) begin
                e_lambda$d = magnified;
            end
        end
        out_valid = e_valid$q;
        out_s = e_st$0$q;
        out_t = e_st$1$q;
        out_lambda = e_lambda$q;
    end
    
endmodule // texture_path$unit$coords


module texture_path$unit$coords$b1_dq$0(d,q,clock);
    
    // Module arguments
    input wire  [29:0] d;
    output reg  [29:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 30'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$b1_dq$0


module texture_path$unit$coords$b1_dq$1(d,q,clock);
    
    // Module arguments
    input wire  [29:0] d;
    output reg  [29:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 30'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$b1_dq$1


module texture_path$unit$coords$b1_dxq$0(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$b1_dxq$0


module texture_path$unit$coords$b1_dxq$1(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$b1_dxq$1


module texture_path$unit$coords$b1_dxq$2(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$b1_dxq$2


module texture_path$unit$coords$b1_dxq$3(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$b1_dxq$3


module texture_path$unit$coords$b1_hs(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$b1_hs


module texture_path$unit$coords$b1_lz(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$b1_lz


module texture_path$unit$coords$b1_p$0(d,q,clock);
    
    // Module arguments
    input wire  [55:0] d;
    output reg  [55:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 56'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$b1_p$0


module texture_path$unit$coords$b1_p$1(d,q,clock);
    
    // Module arguments
    input wire  [55:0] d;
    output reg  [55:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 56'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$b1_p$1


module texture_path$unit$coords$b1_r(d,q,clock);
    
    // Module arguments
    input wire  [26:0] d;
    output reg  [26:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 27'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$b1_r


module texture_path$unit$coords$b1_sh(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$b1_sh


module texture_path$unit$coords$b1_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$b1_valid


module texture_path$unit$coords$b1_ws(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$b1_ws


module texture_path$unit$coords$b_dq$0(d,q,clock);
    
    // Module arguments
    input wire  [29:0] d;
    output reg  [29:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 30'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$b_dq$0


module texture_path$unit$coords$b_dq$1(d,q,clock);
    
    // Module arguments
    input wire  [29:0] d;
    output reg  [29:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 30'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$b_dq$1


module texture_path$unit$coords$b_dxq$0(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$b_dxq$0


module texture_path$unit$coords$b_dxq$1(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$b_dxq$1


module texture_path$unit$coords$b_dxq$2(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$b_dxq$2


module texture_path$unit$coords$b_dxq$3(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$b_dxq$3


module texture_path$unit$coords$b_hs(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$b_hs


module texture_path$unit$coords$b_lz(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$b_lz


module texture_path$unit$coords$b_r(d,q,clock);
    
    // Module arguments
    input wire  [26:0] d;
    output reg  [26:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 27'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$b_r


module texture_path$unit$coords$b_st$0(d,q,clock);
    
    // Module arguments
    input wire  [28:0] d;
    output reg  [28:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 29'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$b_st$0


module texture_path$unit$coords$b_st$1(d,q,clock);
    
    // Module arguments
    input wire  [28:0] d;
    output reg  [28:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 29'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$b_st$1


module texture_path$unit$coords$b_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$b_valid


module texture_path$unit$coords$b_ws(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$b_ws


module texture_path$unit$coords$c1_dxq$0(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$c1_dxq$0


module texture_path$unit$coords$c1_dxq$1(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$c1_dxq$1


module texture_path$unit$coords$c1_dxq$2(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$c1_dxq$2


module texture_path$unit$coords$c1_dxq$3(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$c1_dxq$3


module texture_path$unit$coords$c1_hs(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$c1_hs


module texture_path$unit$coords$c1_lz(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$c1_lz


module texture_path$unit$coords$c1_p$0(d,q,clock);
    
    // Module arguments
    input wire  [34:0] d;
    output reg  [34:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 35'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$c1_p$0


module texture_path$unit$coords$c1_p$1(d,q,clock);
    
    // Module arguments
    input wire  [34:0] d;
    output reg  [34:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 35'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$c1_p$1


module texture_path$unit$coords$c1_p$2(d,q,clock);
    
    // Module arguments
    input wire  [34:0] d;
    output reg  [34:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 35'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$c1_p$2


module texture_path$unit$coords$c1_p$3(d,q,clock);
    
    // Module arguments
    input wire  [34:0] d;
    output reg  [34:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 35'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$c1_p$3


module texture_path$unit$coords$c1_r(d,q,clock);
    
    // Module arguments
    input wire  [26:0] d;
    output reg  [26:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 27'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$c1_r


module texture_path$unit$coords$c1_st$0(d,q,clock);
    
    // Module arguments
    input wire  [28:0] d;
    output reg  [28:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 29'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$c1_st$0


module texture_path$unit$coords$c1_st$1(d,q,clock);
    
    // Module arguments
    input wire  [28:0] d;
    output reg  [28:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 29'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$c1_st$1


module texture_path$unit$coords$c1_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$c1_valid


module texture_path$unit$coords$c1_ws(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$c1_ws


module texture_path$unit$coords$c_lz(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$c_lz


module texture_path$unit$coords$c_r(d,q,clock);
    
    // Module arguments
    input wire  [26:0] d;
    output reg  [26:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 27'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$c_r


module texture_path$unit$coords$c_st$0(d,q,clock);
    
    // Module arguments
    input wire  [28:0] d;
    output reg  [28:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 29'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$c_st$0


module texture_path$unit$coords$c_st$1(d,q,clock);
    
    // Module arguments
    input wire  [28:0] d;
    output reg  [28:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 29'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$c_st$1


module texture_path$unit$coords$c_u$0(d,q,clock);
    
    // Module arguments
    input wire  [46:0] d;
    output reg  [46:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 47'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$c_u$0


module texture_path$unit$coords$c_u$1(d,q,clock);
    
    // Module arguments
    input wire  [46:0] d;
    output reg  [46:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 47'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$c_u$1


module texture_path$unit$coords$c_u$2(d,q,clock);
    
    // Module arguments
    input wire  [46:0] d;
    output reg  [46:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 47'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$c_u$2


module texture_path$unit$coords$c_u$3(d,q,clock);
    
    // Module arguments
    input wire  [46:0] d;
    output reg  [46:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 47'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$c_u$3


module texture_path$unit$coords$c_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$c_valid


module texture_path$unit$coords$d_lz(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$d_lz


module texture_path$unit$coords$d_m(d,q,clock);
    
    // Module arguments
    input wire  [94:0] d;
    output reg  [94:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 95'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$d_m


module texture_path$unit$coords$d_r(d,q,clock);
    
    // Module arguments
    input wire  [26:0] d;
    output reg  [26:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 27'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$d_r


module texture_path$unit$coords$d_st$0(d,q,clock);
    
    // Module arguments
    input wire  [28:0] d;
    output reg  [28:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 29'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$d_st$0


module texture_path$unit$coords$d_st$1(d,q,clock);
    
    // Module arguments
    input wire  [28:0] d;
    output reg  [28:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 29'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$d_st$1


module texture_path$unit$coords$d_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$d_valid


module texture_path$unit$coords$dl_dq_x$0(d,q,clock);
    
    // Module arguments
    input wire  [29:0] d;
    output reg  [29:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 30'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dq_x$0


module texture_path$unit$coords$dl_dq_x$1(d,q,clock);
    
    // Module arguments
    input wire  [29:0] d;
    output reg  [29:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 30'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dq_x$1


module texture_path$unit$coords$dl_dq_x$10(d,q,clock);
    
    // Module arguments
    input wire  [29:0] d;
    output reg  [29:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 30'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dq_x$10


module texture_path$unit$coords$dl_dq_x$11(d,q,clock);
    
    // Module arguments
    input wire  [29:0] d;
    output reg  [29:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 30'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dq_x$11


module texture_path$unit$coords$dl_dq_x$12(d,q,clock);
    
    // Module arguments
    input wire  [29:0] d;
    output reg  [29:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 30'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dq_x$12


module texture_path$unit$coords$dl_dq_x$2(d,q,clock);
    
    // Module arguments
    input wire  [29:0] d;
    output reg  [29:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 30'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dq_x$2


module texture_path$unit$coords$dl_dq_x$3(d,q,clock);
    
    // Module arguments
    input wire  [29:0] d;
    output reg  [29:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 30'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dq_x$3


module texture_path$unit$coords$dl_dq_x$4(d,q,clock);
    
    // Module arguments
    input wire  [29:0] d;
    output reg  [29:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 30'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dq_x$4


module texture_path$unit$coords$dl_dq_x$5(d,q,clock);
    
    // Module arguments
    input wire  [29:0] d;
    output reg  [29:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 30'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dq_x$5


module texture_path$unit$coords$dl_dq_x$6(d,q,clock);
    
    // Module arguments
    input wire  [29:0] d;
    output reg  [29:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 30'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dq_x$6


module texture_path$unit$coords$dl_dq_x$7(d,q,clock);
    
    // Module arguments
    input wire  [29:0] d;
    output reg  [29:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 30'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dq_x$7


module texture_path$unit$coords$dl_dq_x$8(d,q,clock);
    
    // Module arguments
    input wire  [29:0] d;
    output reg  [29:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 30'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dq_x$8


module texture_path$unit$coords$dl_dq_x$9(d,q,clock);
    
    // Module arguments
    input wire  [29:0] d;
    output reg  [29:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 30'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dq_x$9


module texture_path$unit$coords$dl_dq_y$0(d,q,clock);
    
    // Module arguments
    input wire  [29:0] d;
    output reg  [29:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 30'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dq_y$0


module texture_path$unit$coords$dl_dq_y$1(d,q,clock);
    
    // Module arguments
    input wire  [29:0] d;
    output reg  [29:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 30'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dq_y$1


module texture_path$unit$coords$dl_dq_y$10(d,q,clock);
    
    // Module arguments
    input wire  [29:0] d;
    output reg  [29:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 30'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dq_y$10


module texture_path$unit$coords$dl_dq_y$11(d,q,clock);
    
    // Module arguments
    input wire  [29:0] d;
    output reg  [29:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 30'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dq_y$11


module texture_path$unit$coords$dl_dq_y$12(d,q,clock);
    
    // Module arguments
    input wire  [29:0] d;
    output reg  [29:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 30'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dq_y$12


module texture_path$unit$coords$dl_dq_y$2(d,q,clock);
    
    // Module arguments
    input wire  [29:0] d;
    output reg  [29:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 30'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dq_y$2


module texture_path$unit$coords$dl_dq_y$3(d,q,clock);
    
    // Module arguments
    input wire  [29:0] d;
    output reg  [29:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 30'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dq_y$3


module texture_path$unit$coords$dl_dq_y$4(d,q,clock);
    
    // Module arguments
    input wire  [29:0] d;
    output reg  [29:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 30'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dq_y$4


module texture_path$unit$coords$dl_dq_y$5(d,q,clock);
    
    // Module arguments
    input wire  [29:0] d;
    output reg  [29:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 30'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dq_y$5


module texture_path$unit$coords$dl_dq_y$6(d,q,clock);
    
    // Module arguments
    input wire  [29:0] d;
    output reg  [29:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 30'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dq_y$6


module texture_path$unit$coords$dl_dq_y$7(d,q,clock);
    
    // Module arguments
    input wire  [29:0] d;
    output reg  [29:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 30'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dq_y$7


module texture_path$unit$coords$dl_dq_y$8(d,q,clock);
    
    // Module arguments
    input wire  [29:0] d;
    output reg  [29:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 30'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dq_y$8


module texture_path$unit$coords$dl_dq_y$9(d,q,clock);
    
    // Module arguments
    input wire  [29:0] d;
    output reg  [29:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 30'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dq_y$9


module texture_path$unit$coords$dl_dsq_x$0(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dsq_x$0


module texture_path$unit$coords$dl_dsq_x$1(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dsq_x$1


module texture_path$unit$coords$dl_dsq_x$10(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dsq_x$10


module texture_path$unit$coords$dl_dsq_x$11(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dsq_x$11


module texture_path$unit$coords$dl_dsq_x$12(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dsq_x$12


module texture_path$unit$coords$dl_dsq_x$2(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dsq_x$2


module texture_path$unit$coords$dl_dsq_x$3(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dsq_x$3


module texture_path$unit$coords$dl_dsq_x$4(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dsq_x$4


module texture_path$unit$coords$dl_dsq_x$5(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dsq_x$5


module texture_path$unit$coords$dl_dsq_x$6(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dsq_x$6


module texture_path$unit$coords$dl_dsq_x$7(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dsq_x$7


module texture_path$unit$coords$dl_dsq_x$8(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dsq_x$8


module texture_path$unit$coords$dl_dsq_x$9(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dsq_x$9


module texture_path$unit$coords$dl_dsq_y$0(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dsq_y$0


module texture_path$unit$coords$dl_dsq_y$1(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dsq_y$1


module texture_path$unit$coords$dl_dsq_y$10(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dsq_y$10


module texture_path$unit$coords$dl_dsq_y$11(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dsq_y$11


module texture_path$unit$coords$dl_dsq_y$12(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dsq_y$12


module texture_path$unit$coords$dl_dsq_y$2(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dsq_y$2


module texture_path$unit$coords$dl_dsq_y$3(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dsq_y$3


module texture_path$unit$coords$dl_dsq_y$4(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dsq_y$4


module texture_path$unit$coords$dl_dsq_y$5(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dsq_y$5


module texture_path$unit$coords$dl_dsq_y$6(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dsq_y$6


module texture_path$unit$coords$dl_dsq_y$7(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dsq_y$7


module texture_path$unit$coords$dl_dsq_y$8(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dsq_y$8


module texture_path$unit$coords$dl_dsq_y$9(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dsq_y$9


module texture_path$unit$coords$dl_dtq_x$0(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dtq_x$0


module texture_path$unit$coords$dl_dtq_x$1(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dtq_x$1


module texture_path$unit$coords$dl_dtq_x$10(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dtq_x$10


module texture_path$unit$coords$dl_dtq_x$11(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dtq_x$11


module texture_path$unit$coords$dl_dtq_x$12(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dtq_x$12


module texture_path$unit$coords$dl_dtq_x$2(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dtq_x$2


module texture_path$unit$coords$dl_dtq_x$3(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dtq_x$3


module texture_path$unit$coords$dl_dtq_x$4(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dtq_x$4


module texture_path$unit$coords$dl_dtq_x$5(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dtq_x$5


module texture_path$unit$coords$dl_dtq_x$6(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dtq_x$6


module texture_path$unit$coords$dl_dtq_x$7(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dtq_x$7


module texture_path$unit$coords$dl_dtq_x$8(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dtq_x$8


module texture_path$unit$coords$dl_dtq_x$9(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dtq_x$9


module texture_path$unit$coords$dl_dtq_y$0(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dtq_y$0


module texture_path$unit$coords$dl_dtq_y$1(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dtq_y$1


module texture_path$unit$coords$dl_dtq_y$10(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dtq_y$10


module texture_path$unit$coords$dl_dtq_y$11(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dtq_y$11


module texture_path$unit$coords$dl_dtq_y$12(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dtq_y$12


module texture_path$unit$coords$dl_dtq_y$2(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dtq_y$2


module texture_path$unit$coords$dl_dtq_y$3(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dtq_y$3


module texture_path$unit$coords$dl_dtq_y$4(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dtq_y$4


module texture_path$unit$coords$dl_dtq_y$5(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dtq_y$5


module texture_path$unit$coords$dl_dtq_y$6(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dtq_y$6


module texture_path$unit$coords$dl_dtq_y$7(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dtq_y$7


module texture_path$unit$coords$dl_dtq_y$8(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dtq_y$8


module texture_path$unit$coords$dl_dtq_y$9(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_dtq_y$9


module texture_path$unit$coords$dl_hs$0(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_hs$0


module texture_path$unit$coords$dl_hs$1(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_hs$1


module texture_path$unit$coords$dl_hs$10(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_hs$10


module texture_path$unit$coords$dl_hs$11(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_hs$11


module texture_path$unit$coords$dl_hs$12(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_hs$12


module texture_path$unit$coords$dl_hs$2(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_hs$2


module texture_path$unit$coords$dl_hs$3(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_hs$3


module texture_path$unit$coords$dl_hs$4(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_hs$4


module texture_path$unit$coords$dl_hs$5(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_hs$5


module texture_path$unit$coords$dl_hs$6(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_hs$6


module texture_path$unit$coords$dl_hs$7(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_hs$7


module texture_path$unit$coords$dl_hs$8(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_hs$8


module texture_path$unit$coords$dl_hs$9(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_hs$9


module texture_path$unit$coords$dl_lz$0(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_lz$0


module texture_path$unit$coords$dl_lz$1(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_lz$1


module texture_path$unit$coords$dl_lz$10(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_lz$10


module texture_path$unit$coords$dl_lz$11(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_lz$11


module texture_path$unit$coords$dl_lz$12(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_lz$12


module texture_path$unit$coords$dl_lz$2(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_lz$2


module texture_path$unit$coords$dl_lz$3(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_lz$3


module texture_path$unit$coords$dl_lz$4(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_lz$4


module texture_path$unit$coords$dl_lz$5(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_lz$5


module texture_path$unit$coords$dl_lz$6(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_lz$6


module texture_path$unit$coords$dl_lz$7(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_lz$7


module texture_path$unit$coords$dl_lz$8(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_lz$8


module texture_path$unit$coords$dl_lz$9(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_lz$9


module texture_path$unit$coords$dl_sq$0(d,q,clock);
    
    // Module arguments
    input wire  [28:0] d;
    output reg  [28:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 29'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_sq$0


module texture_path$unit$coords$dl_sq$1(d,q,clock);
    
    // Module arguments
    input wire  [28:0] d;
    output reg  [28:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 29'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_sq$1


module texture_path$unit$coords$dl_sq$10(d,q,clock);
    
    // Module arguments
    input wire  [28:0] d;
    output reg  [28:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 29'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_sq$10


module texture_path$unit$coords$dl_sq$11(d,q,clock);
    
    // Module arguments
    input wire  [28:0] d;
    output reg  [28:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 29'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_sq$11


module texture_path$unit$coords$dl_sq$12(d,q,clock);
    
    // Module arguments
    input wire  [28:0] d;
    output reg  [28:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 29'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_sq$12


module texture_path$unit$coords$dl_sq$2(d,q,clock);
    
    // Module arguments
    input wire  [28:0] d;
    output reg  [28:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 29'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_sq$2


module texture_path$unit$coords$dl_sq$3(d,q,clock);
    
    // Module arguments
    input wire  [28:0] d;
    output reg  [28:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 29'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_sq$3


module texture_path$unit$coords$dl_sq$4(d,q,clock);
    
    // Module arguments
    input wire  [28:0] d;
    output reg  [28:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 29'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_sq$4


module texture_path$unit$coords$dl_sq$5(d,q,clock);
    
    // Module arguments
    input wire  [28:0] d;
    output reg  [28:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 29'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_sq$5


module texture_path$unit$coords$dl_sq$6(d,q,clock);
    
    // Module arguments
    input wire  [28:0] d;
    output reg  [28:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 29'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_sq$6


module texture_path$unit$coords$dl_sq$7(d,q,clock);
    
    // Module arguments
    input wire  [28:0] d;
    output reg  [28:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 29'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_sq$7


module texture_path$unit$coords$dl_sq$8(d,q,clock);
    
    // Module arguments
    input wire  [28:0] d;
    output reg  [28:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 29'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_sq$8


module texture_path$unit$coords$dl_sq$9(d,q,clock);
    
    // Module arguments
    input wire  [28:0] d;
    output reg  [28:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 29'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_sq$9


module texture_path$unit$coords$dl_tq$0(d,q,clock);
    
    // Module arguments
    input wire  [28:0] d;
    output reg  [28:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 29'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_tq$0


module texture_path$unit$coords$dl_tq$1(d,q,clock);
    
    // Module arguments
    input wire  [28:0] d;
    output reg  [28:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 29'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_tq$1


module texture_path$unit$coords$dl_tq$10(d,q,clock);
    
    // Module arguments
    input wire  [28:0] d;
    output reg  [28:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 29'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_tq$10


module texture_path$unit$coords$dl_tq$11(d,q,clock);
    
    // Module arguments
    input wire  [28:0] d;
    output reg  [28:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 29'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_tq$11


module texture_path$unit$coords$dl_tq$12(d,q,clock);
    
    // Module arguments
    input wire  [28:0] d;
    output reg  [28:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 29'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_tq$12


module texture_path$unit$coords$dl_tq$2(d,q,clock);
    
    // Module arguments
    input wire  [28:0] d;
    output reg  [28:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 29'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_tq$2


module texture_path$unit$coords$dl_tq$3(d,q,clock);
    
    // Module arguments
    input wire  [28:0] d;
    output reg  [28:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 29'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_tq$3


module texture_path$unit$coords$dl_tq$4(d,q,clock);
    
    // Module arguments
    input wire  [28:0] d;
    output reg  [28:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 29'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_tq$4


module texture_path$unit$coords$dl_tq$5(d,q,clock);
    
    // Module arguments
    input wire  [28:0] d;
    output reg  [28:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 29'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_tq$5


module texture_path$unit$coords$dl_tq$6(d,q,clock);
    
    // Module arguments
    input wire  [28:0] d;
    output reg  [28:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 29'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_tq$6


module texture_path$unit$coords$dl_tq$7(d,q,clock);
    
    // Module arguments
    input wire  [28:0] d;
    output reg  [28:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 29'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_tq$7


module texture_path$unit$coords$dl_tq$8(d,q,clock);
    
    // Module arguments
    input wire  [28:0] d;
    output reg  [28:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 29'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_tq$8


module texture_path$unit$coords$dl_tq$9(d,q,clock);
    
    // Module arguments
    input wire  [28:0] d;
    output reg  [28:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 29'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_tq$9


module texture_path$unit$coords$dl_ws$0(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_ws$0


module texture_path$unit$coords$dl_ws$1(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_ws$1


module texture_path$unit$coords$dl_ws$10(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_ws$10


module texture_path$unit$coords$dl_ws$11(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_ws$11


module texture_path$unit$coords$dl_ws$12(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_ws$12


module texture_path$unit$coords$dl_ws$2(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_ws$2


module texture_path$unit$coords$dl_ws$3(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_ws$3


module texture_path$unit$coords$dl_ws$4(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_ws$4


module texture_path$unit$coords$dl_ws$5(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_ws$5


module texture_path$unit$coords$dl_ws$6(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_ws$6


module texture_path$unit$coords$dl_ws$7(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_ws$7


module texture_path$unit$coords$dl_ws$8(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_ws$8


module texture_path$unit$coords$dl_ws$9(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$dl_ws$9


module texture_path$unit$coords$e1_idx$0(d,q,clock);
    
    // Module arguments
    input wire  [9:0] d;
    output reg  [9:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 10'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$e1_idx$0


module texture_path$unit$coords$e1_idx$1(d,q,clock);
    
    // Module arguments
    input wire  [9:0] d;
    output reg  [9:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 10'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$e1_idx$1


module texture_path$unit$coords$e1_lz(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$e1_lz


module texture_path$unit$coords$e1_p$0(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$e1_p$0


module texture_path$unit$coords$e1_p$1(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$e1_p$1


module texture_path$unit$coords$e1_st$0(d,q,clock);
    
    // Module arguments
    input wire  [28:0] d;
    output reg  [28:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 29'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$e1_st$0


module texture_path$unit$coords$e1_st$1(d,q,clock);
    
    // Module arguments
    input wire  [28:0] d;
    output reg  [28:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 29'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$e1_st$1


module texture_path$unit$coords$e1_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$e1_valid


module texture_path$unit$coords$e1_zero(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$e1_zero


module texture_path$unit$coords$e2_idx$0(d,q,clock);
    
    // Module arguments
    input wire  [9:0] d;
    output reg  [9:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 10'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$e2_idx$0


module texture_path$unit$coords$e2_idx$1(d,q,clock);
    
    // Module arguments
    input wire  [9:0] d;
    output reg  [9:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 10'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$e2_idx$1


module texture_path$unit$coords$e2_lz(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$e2_lz


module texture_path$unit$coords$e2_p$0(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$e2_p$0


module texture_path$unit$coords$e2_p$1(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$e2_p$1


module texture_path$unit$coords$e2_st$0(d,q,clock);
    
    // Module arguments
    input wire  [28:0] d;
    output reg  [28:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 29'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$e2_st$0


module texture_path$unit$coords$e2_st$1(d,q,clock);
    
    // Module arguments
    input wire  [28:0] d;
    output reg  [28:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 29'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$e2_st$1


module texture_path$unit$coords$e2_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$e2_valid


module texture_path$unit$coords$e2_zero(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$e2_zero


module texture_path$unit$coords$e_lambda(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$e_lambda


module texture_path$unit$coords$e_st$0(d,q,clock);
    
    // Module arguments
    input wire  [28:0] d;
    output reg  [28:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 29'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$e_st$0


module texture_path$unit$coords$e_st$1(d,q,clock);
    
    // Module arguments
    input wire  [28:0] d;
    output reg  [28:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 29'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$e_st$1


module texture_path$unit$coords$e_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$e_valid


module texture_path$unit$coords$log_m(address,clock,data);
    
    // Module arguments
    input wire  [9:0] address;
    input wire  clock;
    output reg  [11:0] data;
    
    // Update code (custom)
    reg[11:0] mem [1023:0];
    
    initial begin
    mem[10'b0] = 12'h0;
    mem[10'b1] = 12'h1;
    mem[10'b10] = 12'h2;
    mem[10'b11] = 12'h3;
    mem[10'b100] = 12'h3;
    mem[10'b101] = 12'h4;
    mem[10'b110] = 12'h5;
    mem[10'b111] = 12'h5;
    mem[10'b1000] = 12'h6;
    mem[10'b1001] = 12'h7;
    mem[10'b1010] = 12'h8;
    mem[10'b1011] = 12'h8;
    mem[10'b1100] = 12'h9;
    mem[10'b1101] = 12'ha;
    mem[10'b1110] = 12'ha;
    mem[10'b1111] = 12'hb;
    mem[10'b10000] = 12'hc;
    mem[10'b10001] = 12'hd;
    mem[10'b10010] = 12'hd;
    mem[10'b10011] = 12'he;
    mem[10'b10100] = 12'hf;
    mem[10'b10101] = 12'hf;
    mem[10'b10110] = 12'h10;
    mem[10'b10111] = 12'h11;
    mem[10'b11000] = 12'h11;
    mem[10'b11001] = 12'h12;
    mem[10'b11010] = 12'h13;
    mem[10'b11011] = 12'h14;
    mem[10'b11100] = 12'h14;
    mem[10'b11101] = 12'h15;
    mem[10'b11110] = 12'h16;
    mem[10'b11111] = 12'h16;
    mem[10'b100000] = 12'h17;
    mem[10'b100001] = 12'h18;
    mem[10'b100010] = 12'h18;
    mem[10'b100011] = 12'h19;
    mem[10'b100100] = 12'h1a;
    mem[10'b100101] = 12'h1b;
    mem[10'b100110] = 12'h1b;
    mem[10'b100111] = 12'h1c;
    mem[10'b101000] = 12'h1d;
    mem[10'b101001] = 12'h1d;
    mem[10'b101010] = 12'h1e;
    mem[10'b101011] = 12'h1f;
    mem[10'b101100] = 12'h1f;
    mem[10'b101101] = 12'h20;
    mem[10'b101110] = 12'h21;
    mem[10'b101111] = 12'h21;
    mem[10'b110000] = 12'h22;
    mem[10'b110001] = 12'h23;
    mem[10'b110010] = 12'h24;
    mem[10'b110011] = 12'h24;
    mem[10'b110100] = 12'h25;
    mem[10'b110101] = 12'h26;
    mem[10'b110110] = 12'h26;
    mem[10'b110111] = 12'h27;
    mem[10'b111000] = 12'h28;
    mem[10'b111001] = 12'h28;
    mem[10'b111010] = 12'h29;
    mem[10'b111011] = 12'h2a;
    mem[10'b111100] = 12'h2a;
    mem[10'b111101] = 12'h2b;
    mem[10'b111110] = 12'h2c;
    mem[10'b111111] = 12'h2c;
    mem[10'b1000000] = 12'h2d;
    mem[10'b1000001] = 12'h2e;
    mem[10'b1000010] = 12'h2e;
    mem[10'b1000011] = 12'h2f;
    mem[10'b1000100] = 12'h30;
    mem[10'b1000101] = 12'h31;
    mem[10'b1000110] = 12'h31;
    mem[10'b1000111] = 12'h32;
    mem[10'b1001000] = 12'h33;
    mem[10'b1001001] = 12'h33;
    mem[10'b1001010] = 12'h34;
    mem[10'b1001011] = 12'h35;
    mem[10'b1001100] = 12'h35;
    mem[10'b1001101] = 12'h36;
    mem[10'b1001110] = 12'h37;
    mem[10'b1001111] = 12'h37;
    mem[10'b1010000] = 12'h38;
    mem[10'b1010001] = 12'h39;
    mem[10'b1010010] = 12'h39;
    mem[10'b1010011] = 12'h3a;
    mem[10'b1010100] = 12'h3b;
    mem[10'b1010101] = 12'h3b;
    mem[10'b1010110] = 12'h3c;
    mem[10'b1010111] = 12'h3d;
    mem[10'b1011000] = 12'h3d;
    mem[10'b1011001] = 12'h3e;
    mem[10'b1011010] = 12'h3f;
    mem[10'b1011011] = 12'h3f;
    mem[10'b1011100] = 12'h40;
    mem[10'b1011101] = 12'h41;
    mem[10'b1011110] = 12'h41;
    mem[10'b1011111] = 12'h42;
    mem[10'b1100000] = 12'h43;
    mem[10'b1100001] = 12'h43;
    mem[10'b1100010] = 12'h44;
    mem[10'b1100011] = 12'h44;
    mem[10'b1100100] = 12'h45;
    mem[10'b1100101] = 12'h46;
    mem[10'b1100110] = 12'h46;
    mem[10'b1100111] = 12'h47;
    mem[10'b1101000] = 12'h48;
    mem[10'b1101001] = 12'h48;
    mem[10'b1101010] = 12'h49;
    mem[10'b1101011] = 12'h4a;
    mem[10'b1101100] = 12'h4a;
    mem[10'b1101101] = 12'h4b;
    mem[10'b1101110] = 12'h4c;
    mem[10'b1101111] = 12'h4c;
    mem[10'b1110000] = 12'h4d;
    mem[10'b1110001] = 12'h4e;
    mem[10'b1110010] = 12'h4e;
    mem[10'b1110011] = 12'h4f;
    mem[10'b1110100] = 12'h50;
    mem[10'b1110101] = 12'h50;
    mem[10'b1110110] = 12'h51;
    mem[10'b1110111] = 12'h52;
    mem[10'b1111000] = 12'h52;
    mem[10'b1111001] = 12'h53;
    mem[10'b1111010] = 12'h53;
    mem[10'b1111011] = 12'h54;
    mem[10'b1111100] = 12'h55;
    mem[10'b1111101] = 12'h55;
    mem[10'b1111110] = 12'h56;
    mem[10'b1111111] = 12'h57;
    mem[10'b10000000] = 12'h57;
    mem[10'b10000001] = 12'h58;
    mem[10'b10000010] = 12'h59;
    mem[10'b10000011] = 12'h59;
    mem[10'b10000100] = 12'h5a;
    mem[10'b10000101] = 12'h5b;
    mem[10'b10000110] = 12'h5b;
    mem[10'b10000111] = 12'h5c;
    mem[10'b10001000] = 12'h5c;
    mem[10'b10001001] = 12'h5d;
    mem[10'b10001010] = 12'h5e;
    mem[10'b10001011] = 12'h5e;
    mem[10'b10001100] = 12'h5f;
    mem[10'b10001101] = 12'h60;
    mem[10'b10001110] = 12'h60;
    mem[10'b10001111] = 12'h61;
    mem[10'b10010000] = 12'h62;
    mem[10'b10010001] = 12'h62;
    mem[10'b10010010] = 12'h63;
    mem[10'b10010011] = 12'h63;
    mem[10'b10010100] = 12'h64;
    mem[10'b10010101] = 12'h65;
    mem[10'b10010110] = 12'h65;
    mem[10'b10010111] = 12'h66;
    mem[10'b10011000] = 12'h67;
    mem[10'b10011001] = 12'h67;
    mem[10'b10011010] = 12'h68;
    mem[10'b10011011] = 12'h68;
    mem[10'b10011100] = 12'h69;
    mem[10'b10011101] = 12'h6a;
    mem[10'b10011110] = 12'h6a;
    mem[10'b10011111] = 12'h6b;
    mem[10'b10100000] = 12'h6c;
    mem[10'b10100001] = 12'h6c;
    mem[10'b10100010] = 12'h6d;
    mem[10'b10100011] = 12'h6d;
    mem[10'b10100100] = 12'h6e;
    mem[10'b10100101] = 12'h6f;
    mem[10'b10100110] = 12'h6f;
    mem[10'b10100111] = 12'h70;
    mem[10'b10101000] = 12'h71;
    mem[10'b10101001] = 12'h71;
    mem[10'b10101010] = 12'h72;
    mem[10'b10101011] = 12'h72;
    mem[10'b10101100] = 12'h73;
    mem[10'b10101101] = 12'h74;
    mem[10'b10101110] = 12'h74;
    mem[10'b10101111] = 12'h75;
    mem[10'b10110000] = 12'h75;
    mem[10'b10110001] = 12'h76;
    mem[10'b10110010] = 12'h77;
    mem[10'b10110011] = 12'h77;
    mem[10'b10110100] = 12'h78;
    mem[10'b10110101] = 12'h79;
    mem[10'b10110110] = 12'h79;
    mem[10'b10110111] = 12'h7a;
    mem[10'b10111000] = 12'h7a;
    mem[10'b10111001] = 12'h7b;
    mem[10'b10111010] = 12'h7c;
    mem[10'b10111011] = 12'h7c;
    mem[10'b10111100] = 12'h7d;
    mem[10'b10111101] = 12'h7d;
    mem[10'b10111110] = 12'h7e;
    mem[10'b10111111] = 12'h7f;
    mem[10'b11000000] = 12'h7f;
    mem[10'b11000001] = 12'h80;
    mem[10'b11000010] = 12'h80;
    mem[10'b11000011] = 12'h81;
    mem[10'b11000100] = 12'h82;
    mem[10'b11000101] = 12'h82;
    mem[10'b11000110] = 12'h83;
    mem[10'b11000111] = 12'h83;
    mem[10'b11001000] = 12'h84;
    mem[10'b11001001] = 12'h85;
    mem[10'b11001010] = 12'h85;
    mem[10'b11001011] = 12'h86;
    mem[10'b11001100] = 12'h86;
    mem[10'b11001101] = 12'h87;
    mem[10'b11001110] = 12'h88;
    mem[10'b11001111] = 12'h88;
    mem[10'b11010000] = 12'h89;
    mem[10'b11010001] = 12'h89;
    mem[10'b11010010] = 12'h8a;
    mem[10'b11010011] = 12'h8b;
    mem[10'b11010100] = 12'h8b;
    mem[10'b11010101] = 12'h8c;
    mem[10'b11010110] = 12'h8c;
    mem[10'b11010111] = 12'h8d;
    mem[10'b11011000] = 12'h8e;
    mem[10'b11011001] = 12'h8e;
    mem[10'b11011010] = 12'h8f;
    mem[10'b11011011] = 12'h8f;
    mem[10'b11011100] = 12'h90;
    mem[10'b11011101] = 12'h91;
    mem[10'b11011110] = 12'h91;
    mem[10'b11011111] = 12'h92;
    mem[10'b11100000] = 12'h92;
    mem[10'b11100001] = 12'h93;
    mem[10'b11100010] = 12'h94;
    mem[10'b11100011] = 12'h94;
    mem[10'b11100100] = 12'h95;
    mem[10'b11100101] = 12'h95;
    mem[10'b11100110] = 12'h96;
    mem[10'b11100111] = 12'h97;
    mem[10'b11101000] = 12'h97;
    mem[10'b11101001] = 12'h98;
    mem[10'b11101010] = 12'h98;
    mem[10'b11101011] = 12'h99;
    mem[10'b11101100] = 12'h99;
    mem[10'b11101101] = 12'h9a;
    mem[10'b11101110] = 12'h9b;
    mem[10'b11101111] = 12'h9b;
    mem[10'b11110000] = 12'h9c;
    mem[10'b11110001] = 12'h9c;
    mem[10'b11110010] = 12'h9d;
    mem[10'b11110011] = 12'h9e;
    mem[10'b11110100] = 12'h9e;
    mem[10'b11110101] = 12'h9f;
    mem[10'b11110110] = 12'h9f;
    mem[10'b11110111] = 12'ha0;
    mem[10'b11111000] = 12'ha0;
    mem[10'b11111001] = 12'ha1;
    mem[10'b11111010] = 12'ha2;
    mem[10'b11111011] = 12'ha2;
    mem[10'b11111100] = 12'ha3;
    mem[10'b11111101] = 12'ha3;
    mem[10'b11111110] = 12'ha4;
    mem[10'b11111111] = 12'ha5;
    mem[10'b100000000] = 12'ha5;
    mem[10'b100000001] = 12'ha6;
    mem[10'b100000010] = 12'ha6;
    mem[10'b100000011] = 12'ha7;
    mem[10'b100000100] = 12'ha7;
    mem[10'b100000101] = 12'ha8;
    mem[10'b100000110] = 12'ha9;
    mem[10'b100000111] = 12'ha9;
    mem[10'b100001000] = 12'haa;
    mem[10'b100001001] = 12'haa;
    mem[10'b100001010] = 12'hab;
    mem[10'b100001011] = 12'hab;
    mem[10'b100001100] = 12'hac;
    mem[10'b100001101] = 12'had;
    mem[10'b100001110] = 12'had;
    mem[10'b100001111] = 12'hae;
    mem[10'b100010000] = 12'hae;
    mem[10'b100010001] = 12'haf;
    mem[10'b100010010] = 12'haf;
    mem[10'b100010011] = 12'hb0;
    mem[10'b100010100] = 12'hb1;
    mem[10'b100010101] = 12'hb1;
    mem[10'b100010110] = 12'hb2;
    mem[10'b100010111] = 12'hb2;
    mem[10'b100011000] = 12'hb3;
    mem[10'b100011001] = 12'hb3;
    mem[10'b100011010] = 12'hb4;
    mem[10'b100011011] = 12'hb5;
    mem[10'b100011100] = 12'hb5;
    mem[10'b100011101] = 12'hb6;
    mem[10'b100011110] = 12'hb6;
    mem[10'b100011111] = 12'hb7;
    mem[10'b100100000] = 12'hb7;
    mem[10'b100100001] = 12'hb8;
    mem[10'b100100010] = 12'hb8;
    mem[10'b100100011] = 12'hb9;
    mem[10'b100100100] = 12'hba;
    mem[10'b100100101] = 12'hba;
    mem[10'b100100110] = 12'hbb;
    mem[10'b100100111] = 12'hbb;
    mem[10'b100101000] = 12'hbc;
    mem[10'b100101001] = 12'hbc;
    mem[10'b100101010] = 12'hbd;
    mem[10'b100101011] = 12'hbe;
    mem[10'b100101100] = 12'hbe;
    mem[10'b100101101] = 12'hbf;
    mem[10'b100101110] = 12'hbf;
    mem[10'b100101111] = 12'hc0;
    mem[10'b100110000] = 12'hc0;
    mem[10'b100110001] = 12'hc1;
    mem[10'b100110010] = 12'hc1;
    mem[10'b100110011] = 12'hc2;
    mem[10'b100110100] = 12'hc3;
    mem[10'b100110101] = 12'hc3;
    mem[10'b100110110] = 12'hc4;
    mem[10'b100110111] = 12'hc4;
    mem[10'b100111000] = 12'hc5;
    mem[10'b100111001] = 12'hc5;
    mem[10'b100111010] = 12'hc6;
    mem[10'b100111011] = 12'hc6;
    mem[10'b100111100] = 12'hc7;
    mem[10'b100111101] = 12'hc7;
    mem[10'b100111110] = 12'hc8;
    mem[10'b100111111] = 12'hc9;
    mem[10'b101000000] = 12'hc9;
    mem[10'b101000001] = 12'hca;
    mem[10'b101000010] = 12'hca;
    mem[10'b101000011] = 12'hcb;
    mem[10'b101000100] = 12'hcb;
    mem[10'b101000101] = 12'hcc;
    mem[10'b101000110] = 12'hcc;
    mem[10'b101000111] = 12'hcd;
    mem[10'b101001000] = 12'hce;
    mem[10'b101001001] = 12'hce;
    mem[10'b101001010] = 12'hcf;
    mem[10'b101001011] = 12'hcf;
    mem[10'b101001100] = 12'hd0;
    mem[10'b101001101] = 12'hd0;
    mem[10'b101001110] = 12'hd1;
    mem[10'b101001111] = 12'hd1;
    mem[10'b101010000] = 12'hd2;
    mem[10'b101010001] = 12'hd2;
    mem[10'b101010010] = 12'hd3;
    mem[10'b101010011] = 12'hd4;
    mem[10'b101010100] = 12'hd4;
    mem[10'b101010101] = 12'hd5;
    mem[10'b101010110] = 12'hd5;
    mem[10'b101010111] = 12'hd6;
    mem[10'b101011000] = 12'hd6;
    mem[10'b101011001] = 12'hd7;
    mem[10'b101011010] = 12'hd7;
    mem[10'b101011011] = 12'hd8;
    mem[10'b101011100] = 12'hd8;
    mem[10'b101011101] = 12'hd9;
    mem[10'b101011110] = 12'hd9;
    mem[10'b101011111] = 12'hda;
    mem[10'b101100000] = 12'hdb;
    mem[10'b101100001] = 12'hdb;
    mem[10'b101100010] = 12'hdc;
    mem[10'b101100011] = 12'hdc;
    mem[10'b101100100] = 12'hdd;
    mem[10'b101100101] = 12'hdd;
    mem[10'b101100110] = 12'hde;
    mem[10'b101100111] = 12'hde;
    mem[10'b101101000] = 12'hdf;
    mem[10'b101101001] = 12'hdf;
    mem[10'b101101010] = 12'he0;
    mem[10'b101101011] = 12'he0;
    mem[10'b101101100] = 12'he1;
    mem[10'b101101101] = 12'he1;
    mem[10'b101101110] = 12'he2;
    mem[10'b101101111] = 12'he3;
    mem[10'b101110000] = 12'he3;
    mem[10'b101110001] = 12'he4;
    mem[10'b101110010] = 12'he4;
    mem[10'b101110011] = 12'he5;
    mem[10'b101110100] = 12'he5;
    mem[10'b101110101] = 12'he6;
    mem[10'b101110110] = 12'he6;
    mem[10'b101110111] = 12'he7;
    mem[10'b101111000] = 12'he7;
    mem[10'b101111001] = 12'he8;
    mem[10'b101111010] = 12'he8;
    mem[10'b101111011] = 12'he9;
    mem[10'b101111100] = 12'he9;
    mem[10'b101111101] = 12'hea;
    mem[10'b101111110] = 12'hea;
    mem[10'b101111111] = 12'heb;
    mem[10'b110000000] = 12'heb;
    mem[10'b110000001] = 12'hec;
    mem[10'b110000010] = 12'hed;
    mem[10'b110000011] = 12'hed;
    mem[10'b110000100] = 12'hee;
    mem[10'b110000101] = 12'hee;
    mem[10'b110000110] = 12'hef;
    mem[10'b110000111] = 12'hef;
    mem[10'b110001000] = 12'hf0;
    mem[10'b110001001] = 12'hf0;
    mem[10'b110001010] = 12'hf1;
    mem[10'b110001011] = 12'hf1;
    mem[10'b110001100] = 12'hf2;
    mem[10'b110001101] = 12'hf2;
    mem[10'b110001110] = 12'hf3;
    mem[10'b110001111] = 12'hf3;
    mem[10'b110010000] = 12'hf4;
    mem[10'b110010001] = 12'hf4;
    mem[10'b110010010] = 12'hf5;
    mem[10'b110010011] = 12'hf5;
    mem[10'b110010100] = 12'hf6;
    mem[10'b110010101] = 12'hf6;
    mem[10'b110010110] = 12'hf7;
    mem[10'b110010111] = 12'hf7;
    mem[10'b110011000] = 12'hf8;
    mem[10'b110011001] = 12'hf8;
    mem[10'b110011010] = 12'hf9;
    mem[10'b110011011] = 12'hfa;
    mem[10'b110011100] = 12'hfa;
    mem[10'b110011101] = 12'hfb;
    mem[10'b110011110] = 12'hfb;
    mem[10'b110011111] = 12'hfc;
    mem[10'b110100000] = 12'hfc;
    mem[10'b110100001] = 12'hfd;
    mem[10'b110100010] = 12'hfd;
    mem[10'b110100011] = 12'hfe;
    mem[10'b110100100] = 12'hfe;
    mem[10'b110100101] = 12'hff;
    mem[10'b110100110] = 12'hff;
    mem[10'b110100111] = 12'h100;
    mem[10'b110101000] = 12'h100;
    mem[10'b110101001] = 12'h101;
    mem[10'b110101010] = 12'h101;
    mem[10'b110101011] = 12'h102;
    mem[10'b110101100] = 12'h102;
    mem[10'b110101101] = 12'h103;
    mem[10'b110101110] = 12'h103;
    mem[10'b110101111] = 12'h104;
    mem[10'b110110000] = 12'h104;
    mem[10'b110110001] = 12'h105;
    mem[10'b110110010] = 12'h105;
    mem[10'b110110011] = 12'h106;
    mem[10'b110110100] = 12'h106;
    mem[10'b110110101] = 12'h107;
    mem[10'b110110110] = 12'h107;
    mem[10'b110110111] = 12'h108;
    mem[10'b110111000] = 12'h108;
    mem[10'b110111001] = 12'h109;
    mem[10'b110111010] = 12'h109;
    mem[10'b110111011] = 12'h10a;
    mem[10'b110111100] = 12'h10a;
    mem[10'b110111101] = 12'h10b;
    mem[10'b110111110] = 12'h10b;
    mem[10'b110111111] = 12'h10c;
    mem[10'b111000000] = 12'h10c;
    mem[10'b111000001] = 12'h10d;
    mem[10'b111000010] = 12'h10d;
    mem[10'b111000011] = 12'h10e;
    mem[10'b111000100] = 12'h10e;
    mem[10'b111000101] = 12'h10f;
    mem[10'b111000110] = 12'h10f;
    mem[10'b111000111] = 12'h110;
    mem[10'b111001000] = 12'h110;
    mem[10'b111001001] = 12'h111;
    mem[10'b111001010] = 12'h111;
    mem[10'b111001011] = 12'h112;
    mem[10'b111001100] = 12'h112;
    mem[10'b111001101] = 12'h113;
    mem[10'b111001110] = 12'h113;
    mem[10'b111001111] = 12'h114;
    mem[10'b111010000] = 12'h114;
    mem[10'b111010001] = 12'h115;
    mem[10'b111010010] = 12'h115;
    mem[10'b111010011] = 12'h116;
    mem[10'b111010100] = 12'h116;
    mem[10'b111010101] = 12'h117;
    mem[10'b111010110] = 12'h117;
    mem[10'b111010111] = 12'h118;
    mem[10'b111011000] = 12'h118;
    mem[10'b111011001] = 12'h119;
    mem[10'b111011010] = 12'h119;
    mem[10'b111011011] = 12'h11a;
    mem[10'b111011100] = 12'h11a;
    mem[10'b111011101] = 12'h11b;
    mem[10'b111011110] = 12'h11b;
    mem[10'b111011111] = 12'h11c;
    mem[10'b111100000] = 12'h11c;
    mem[10'b111100001] = 12'h11d;
    mem[10'b111100010] = 12'h11d;
    mem[10'b111100011] = 12'h11e;
    mem[10'b111100100] = 12'h11e;
    mem[10'b111100101] = 12'h11f;
    mem[10'b111100110] = 12'h11f;
    mem[10'b111100111] = 12'h120;
    mem[10'b111101000] = 12'h120;
    mem[10'b111101001] = 12'h121;
    mem[10'b111101010] = 12'h121;
    mem[10'b111101011] = 12'h122;
    mem[10'b111101100] = 12'h122;
    mem[10'b111101101] = 12'h123;
    mem[10'b111101110] = 12'h123;
    mem[10'b111101111] = 12'h124;
    mem[10'b111110000] = 12'h124;
    mem[10'b111110001] = 12'h124;
    mem[10'b111110010] = 12'h125;
    mem[10'b111110011] = 12'h125;
    mem[10'b111110100] = 12'h126;
    mem[10'b111110101] = 12'h126;
    mem[10'b111110110] = 12'h127;
    mem[10'b111110111] = 12'h127;
    mem[10'b111111000] = 12'h128;
    mem[10'b111111001] = 12'h128;
    mem[10'b111111010] = 12'h129;
    mem[10'b111111011] = 12'h129;
    mem[10'b111111100] = 12'h12a;
    mem[10'b111111101] = 12'h12a;
    mem[10'b111111110] = 12'h12b;
    mem[10'b111111111] = 12'h12b;
    mem[10'b1000000000] = 12'h12c;
    mem[10'b1000000001] = 12'h12c;
    mem[10'b1000000010] = 12'h12d;
    mem[10'b1000000011] = 12'h12d;
    mem[10'b1000000100] = 12'h12e;
    mem[10'b1000000101] = 12'h12e;
    mem[10'b1000000110] = 12'h12f;
    mem[10'b1000000111] = 12'h12f;
    mem[10'b1000001000] = 12'h130;
    mem[10'b1000001001] = 12'h130;
    mem[10'b1000001010] = 12'h131;
    mem[10'b1000001011] = 12'h131;
    mem[10'b1000001100] = 12'h131;
    mem[10'b1000001101] = 12'h132;
    mem[10'b1000001110] = 12'h132;
    mem[10'b1000001111] = 12'h133;
    mem[10'b1000010000] = 12'h133;
    mem[10'b1000010001] = 12'h134;
    mem[10'b1000010010] = 12'h134;
    mem[10'b1000010011] = 12'h135;
    mem[10'b1000010100] = 12'h135;
    mem[10'b1000010101] = 12'h136;
    mem[10'b1000010110] = 12'h136;
    mem[10'b1000010111] = 12'h137;
    mem[10'b1000011000] = 12'h137;
    mem[10'b1000011001] = 12'h138;
    mem[10'b1000011010] = 12'h138;
    mem[10'b1000011011] = 12'h139;
    mem[10'b1000011100] = 12'h139;
    mem[10'b1000011101] = 12'h13a;
    mem[10'b1000011110] = 12'h13a;
    mem[10'b1000011111] = 12'h13a;
    mem[10'b1000100000] = 12'h13b;
    mem[10'b1000100001] = 12'h13b;
    mem[10'b1000100010] = 12'h13c;
    mem[10'b1000100011] = 12'h13c;
    mem[10'b1000100100] = 12'h13d;
    mem[10'b1000100101] = 12'h13d;
    mem[10'b1000100110] = 12'h13e;
    mem[10'b1000100111] = 12'h13e;
    mem[10'b1000101000] = 12'h13f;
    mem[10'b1000101001] = 12'h13f;
    mem[10'b1000101010] = 12'h140;
    mem[10'b1000101011] = 12'h140;
    mem[10'b1000101100] = 12'h141;
    mem[10'b1000101101] = 12'h141;
    mem[10'b1000101110] = 12'h142;
    mem[10'b1000101111] = 12'h142;
    mem[10'b1000110000] = 12'h142;
    mem[10'b1000110001] = 12'h143;
    mem[10'b1000110010] = 12'h143;
    mem[10'b1000110011] = 12'h144;
    mem[10'b1000110100] = 12'h144;
    mem[10'b1000110101] = 12'h145;
    mem[10'b1000110110] = 12'h145;
    mem[10'b1000110111] = 12'h146;
    mem[10'b1000111000] = 12'h146;
    mem[10'b1000111001] = 12'h147;
    mem[10'b1000111010] = 12'h147;
    mem[10'b1000111011] = 12'h148;
    mem[10'b1000111100] = 12'h148;
    mem[10'b1000111101] = 12'h148;
    mem[10'b1000111110] = 12'h149;
    mem[10'b1000111111] = 12'h149;
    mem[10'b1001000000] = 12'h14a;
    mem[10'b1001000001] = 12'h14a;
    mem[10'b1001000010] = 12'h14b;
    mem[10'b1001000011] = 12'h14b;
    mem[10'b1001000100] = 12'h14c;
    mem[10'b1001000101] = 12'h14c;
    mem[10'b1001000110] = 12'h14d;
    mem[10'b1001000111] = 12'h14d;
    mem[10'b1001001000] = 12'h14e;
    mem[10'b1001001001] = 12'h14e;
    mem[10'b1001001010] = 12'h14e;
    mem[10'b1001001011] = 12'h14f;
    mem[10'b1001001100] = 12'h14f;
    mem[10'b1001001101] = 12'h150;
    mem[10'b1001001110] = 12'h150;
    mem[10'b1001001111] = 12'h151;
    mem[10'b1001010000] = 12'h151;
    mem[10'b1001010001] = 12'h152;
    mem[10'b1001010010] = 12'h152;
    mem[10'b1001010011] = 12'h153;
    mem[10'b1001010100] = 12'h153;
    mem[10'b1001010101] = 12'h154;
    mem[10'b1001010110] = 12'h154;
    mem[10'b1001010111] = 12'h154;
    mem[10'b1001011000] = 12'h155;
    mem[10'b1001011001] = 12'h155;
    mem[10'b1001011010] = 12'h156;
    mem[10'b1001011011] = 12'h156;
    mem[10'b1001011100] = 12'h157;
    mem[10'b1001011101] = 12'h157;
    mem[10'b1001011110] = 12'h158;
    mem[10'b1001011111] = 12'h158;
    mem[10'b1001100000] = 12'h159;
    mem[10'b1001100001] = 12'h159;
    mem[10'b1001100010] = 12'h159;
    mem[10'b1001100011] = 12'h15a;
    mem[10'b1001100100] = 12'h15a;
    mem[10'b1001100101] = 12'h15b;
    mem[10'b1001100110] = 12'h15b;
    mem[10'b1001100111] = 12'h15c;
    mem[10'b1001101000] = 12'h15c;
    mem[10'b1001101001] = 12'h15d;
    mem[10'b1001101010] = 12'h15d;
    mem[10'b1001101011] = 12'h15d;
    mem[10'b1001101100] = 12'h15e;
    mem[10'b1001101101] = 12'h15e;
    mem[10'b1001101110] = 12'h15f;
    mem[10'b1001101111] = 12'h15f;
    mem[10'b1001110000] = 12'h160;
    mem[10'b1001110001] = 12'h160;
    mem[10'b1001110010] = 12'h161;
    mem[10'b1001110011] = 12'h161;
    mem[10'b1001110100] = 12'h162;
    mem[10'b1001110101] = 12'h162;
    mem[10'b1001110110] = 12'h162;
    mem[10'b1001110111] = 12'h163;
    mem[10'b1001111000] = 12'h163;
    mem[10'b1001111001] = 12'h164;
    mem[10'b1001111010] = 12'h164;
    mem[10'b1001111011] = 12'h165;
    mem[10'b1001111100] = 12'h165;
    mem[10'b1001111101] = 12'h166;
    mem[10'b1001111110] = 12'h166;
    mem[10'b1001111111] = 12'h166;
    mem[10'b1010000000] = 12'h167;
    mem[10'b1010000001] = 12'h167;
    mem[10'b1010000010] = 12'h168;
    mem[10'b1010000011] = 12'h168;
    mem[10'b1010000100] = 12'h169;
    mem[10'b1010000101] = 12'h169;
    mem[10'b1010000110] = 12'h16a;
    mem[10'b1010000111] = 12'h16a;
    mem[10'b1010001000] = 12'h16a;
    mem[10'b1010001001] = 12'h16b;
    mem[10'b1010001010] = 12'h16b;
    mem[10'b1010001011] = 12'h16c;
    mem[10'b1010001100] = 12'h16c;
    mem[10'b1010001101] = 12'h16d;
    mem[10'b1010001110] = 12'h16d;
    mem[10'b1010001111] = 12'h16d;
    mem[10'b1010010000] = 12'h16e;
    mem[10'b1010010001] = 12'h16e;
    mem[10'b1010010010] = 12'h16f;
    mem[10'b1010010011] = 12'h16f;
    mem[10'b1010010100] = 12'h170;
    mem[10'b1010010101] = 12'h170;
    mem[10'b1010010110] = 12'h171;
    mem[10'b1010010111] = 12'h171;
    mem[10'b1010011000] = 12'h171;
    mem[10'b1010011001] = 12'h172;
    mem[10'b1010011010] = 12'h172;
    mem[10'b1010011011] = 12'h173;
    mem[10'b1010011100] = 12'h173;
    mem[10'b1010011101] = 12'h174;
    mem[10'b1010011110] = 12'h174;
    mem[10'b1010011111] = 12'h174;
    mem[10'b1010100000] = 12'h175;
    mem[10'b1010100001] = 12'h175;
    mem[10'b1010100010] = 12'h176;
    mem[10'b1010100011] = 12'h176;
    mem[10'b1010100100] = 12'h177;
    mem[10'b1010100101] = 12'h177;
    mem[10'b1010100110] = 12'h178;
    mem[10'b1010100111] = 12'h178;
    mem[10'b1010101000] = 12'h178;
    mem[10'b1010101001] = 12'h179;
    mem[10'b1010101010] = 12'h179;
    mem[10'b1010101011] = 12'h17a;
    mem[10'b1010101100] = 12'h17a;
    mem[10'b1010101101] = 12'h17b;
    mem[10'b1010101110] = 12'h17b;
    mem[10'b1010101111] = 12'h17b;
    mem[10'b1010110000] = 12'h17c;
    mem[10'b1010110001] = 12'h17c;
    mem[10'b1010110010] = 12'h17d;
    mem[10'b1010110011] = 12'h17d;
    mem[10'b1010110100] = 12'h17e;
    mem[10'b1010110101] = 12'h17e;
    mem[10'b1010110110] = 12'h17e;
    mem[10'b1010110111] = 12'h17f;
    mem[10'b1010111000] = 12'h17f;
    mem[10'b1010111001] = 12'h180;
    mem[10'b1010111010] = 12'h180;
    mem[10'b1010111011] = 12'h181;
    mem[10'b1010111100] = 12'h181;
    mem[10'b1010111101] = 12'h181;
    mem[10'b1010111110] = 12'h182;
    mem[10'b1010111111] = 12'h182;
    mem[10'b1011000000] = 12'h183;
    mem[10'b1011000001] = 12'h183;
    mem[10'b1011000010] = 12'h184;
    mem[10'b1011000011] = 12'h184;
    mem[10'b1011000100] = 12'h184;
    mem[10'b1011000101] = 12'h185;
    mem[10'b1011000110] = 12'h185;
    mem[10'b1011000111] = 12'h186;
    mem[10'b1011001000] = 12'h186;
    mem[10'b1011001001] = 12'h187;
    mem[10'b1011001010] = 12'h187;
    mem[10'b1011001011] = 12'h187;
    mem[10'b1011001100] = 12'h188;
    mem[10'b1011001101] = 12'h188;
    mem[10'b1011001110] = 12'h189;
    mem[10'b1011001111] = 12'h189;
    mem[10'b1011010000] = 12'h18a;
    mem[10'b1011010001] = 12'h18a;
    mem[10'b1011010010] = 12'h18a;
    mem[10'b1011010011] = 12'h18b;
    mem[10'b1011010100] = 12'h18b;
    mem[10'b1011010101] = 12'h18c;
    mem[10'b1011010110] = 12'h18c;
    mem[10'b1011010111] = 12'h18c;
    mem[10'b1011011000] = 12'h18d;
    mem[10'b1011011001] = 12'h18d;
    mem[10'b1011011010] = 12'h18e;
    mem[10'b1011011011] = 12'h18e;
    mem[10'b1011011100] = 12'h18f;
    mem[10'b1011011101] = 12'h18f;
    mem[10'b1011011110] = 12'h18f;
    mem[10'b1011011111] = 12'h190;
    mem[10'b1011100000] = 12'h190;
    mem[10'b1011100001] = 12'h191;
    mem[10'b1011100010] = 12'h191;
    mem[10'b1011100011] = 12'h192;
    mem[10'b1011100100] = 12'h192;
    mem[10'b1011100101] = 12'h192;
    mem[10'b1011100110] = 12'h193;
    mem[10'b1011100111] = 12'h193;
    mem[10'b1011101000] = 12'h194;
    mem[10'b1011101001] = 12'h194;
    mem[10'b1011101010] = 12'h194;
    mem[10'b1011101011] = 12'h195;
    mem[10'b1011101100] = 12'h195;
    mem[10'b1011101101] = 12'h196;
    mem[10'b1011101110] = 12'h196;
    mem[10'b1011101111] = 12'h197;
    mem[10'b1011110000] = 12'h197;
    mem[10'b1011110001] = 12'h197;
    mem[10'b1011110010] = 12'h198;
    mem[10'b1011110011] = 12'h198;
    mem[10'b1011110100] = 12'h199;
    mem[10'b1011110101] = 12'h199;
    mem[10'b1011110110] = 12'h199;
    mem[10'b1011110111] = 12'h19a;
    mem[10'b1011111000] = 12'h19a;
    mem[10'b1011111001] = 12'h19b;
    mem[10'b1011111010] = 12'h19b;
    mem[10'b1011111011] = 12'h19c;
    mem[10'b1011111100] = 12'h19c;
    mem[10'b1011111101] = 12'h19c;
    mem[10'b1011111110] = 12'h19d;
    mem[10'b1011111111] = 12'h19d;
    mem[10'b1100000000] = 12'h19e;
    mem[10'b1100000001] = 12'h19e;
    mem[10'b1100000010] = 12'h19e;
    mem[10'b1100000011] = 12'h19f;
    mem[10'b1100000100] = 12'h19f;
    mem[10'b1100000101] = 12'h1a0;
    mem[10'b1100000110] = 12'h1a0;
    mem[10'b1100000111] = 12'h1a0;
    mem[10'b1100001000] = 12'h1a1;
    mem[10'b1100001001] = 12'h1a1;
    mem[10'b1100001010] = 12'h1a2;
    mem[10'b1100001011] = 12'h1a2;
    mem[10'b1100001100] = 12'h1a3;
    mem[10'b1100001101] = 12'h1a3;
    mem[10'b1100001110] = 12'h1a3;
    mem[10'b1100001111] = 12'h1a4;
    mem[10'b1100010000] = 12'h1a4;
    mem[10'b1100010001] = 12'h1a5;
    mem[10'b1100010010] = 12'h1a5;
    mem[10'b1100010011] = 12'h1a5;
    mem[10'b1100010100] = 12'h1a6;
    mem[10'b1100010101] = 12'h1a6;
    mem[10'b1100010110] = 12'h1a7;
    mem[10'b1100010111] = 12'h1a7;
    mem[10'b1100011000] = 12'h1a7;
    mem[10'b1100011001] = 12'h1a8;
    mem[10'b1100011010] = 12'h1a8;
    mem[10'b1100011011] = 12'h1a9;
    mem[10'b1100011100] = 12'h1a9;
    mem[10'b1100011101] = 12'h1a9;
    mem[10'b1100011110] = 12'h1aa;
    mem[10'b1100011111] = 12'h1aa;
    mem[10'b1100100000] = 12'h1ab;
    mem[10'b1100100001] = 12'h1ab;
    mem[10'b1100100010] = 12'h1ab;
    mem[10'b1100100011] = 12'h1ac;
    mem[10'b1100100100] = 12'h1ac;
    mem[10'b1100100101] = 12'h1ad;
    mem[10'b1100100110] = 12'h1ad;
    mem[10'b1100100111] = 12'h1ad;
    mem[10'b1100101000] = 12'h1ae;
    mem[10'b1100101001] = 12'h1ae;
    mem[10'b1100101010] = 12'h1af;
    mem[10'b1100101011] = 12'h1af;
    mem[10'b1100101100] = 12'h1af;
    mem[10'b1100101101] = 12'h1b0;
    mem[10'b1100101110] = 12'h1b0;
    mem[10'b1100101111] = 12'h1b1;
    mem[10'b1100110000] = 12'h1b1;
    mem[10'b1100110001] = 12'h1b1;
    mem[10'b1100110010] = 12'h1b2;
    mem[10'b1100110011] = 12'h1b2;
    mem[10'b1100110100] = 12'h1b3;
    mem[10'b1100110101] = 12'h1b3;
    mem[10'b1100110110] = 12'h1b3;
    mem[10'b1100110111] = 12'h1b4;
    mem[10'b1100111000] = 12'h1b4;
    mem[10'b1100111001] = 12'h1b5;
    mem[10'b1100111010] = 12'h1b5;
    mem[10'b1100111011] = 12'h1b5;
    mem[10'b1100111100] = 12'h1b6;
    mem[10'b1100111101] = 12'h1b6;
    mem[10'b1100111110] = 12'h1b7;
    mem[10'b1100111111] = 12'h1b7;
    mem[10'b1101000000] = 12'h1b7;
    mem[10'b1101000001] = 12'h1b8;
    mem[10'b1101000010] = 12'h1b8;
    mem[10'b1101000011] = 12'h1b9;
    mem[10'b1101000100] = 12'h1b9;
    mem[10'b1101000101] = 12'h1b9;
    mem[10'b1101000110] = 12'h1ba;
    mem[10'b1101000111] = 12'h1ba;
    mem[10'b1101001000] = 12'h1bb;
    mem[10'b1101001001] = 12'h1bb;
    mem[10'b1101001010] = 12'h1bb;
    mem[10'b1101001011] = 12'h1bc;
    mem[10'b1101001100] = 12'h1bc;
    mem[10'b1101001101] = 12'h1bd;
    mem[10'b1101001110] = 12'h1bd;
    mem[10'b1101001111] = 12'h1bd;
    mem[10'b1101010000] = 12'h1be;
    mem[10'b1101010001] = 12'h1be;
    mem[10'b1101010010] = 12'h1bf;
    mem[10'b1101010011] = 12'h1bf;
    mem[10'b1101010100] = 12'h1bf;
    mem[10'b1101010101] = 12'h1c0;
    mem[10'b1101010110] = 12'h1c0;
    mem[10'b1101010111] = 12'h1c1;
    mem[10'b1101011000] = 12'h1c1;
    mem[10'b1101011001] = 12'h1c1;
    mem[10'b1101011010] = 12'h1c2;
    mem[10'b1101011011] = 12'h1c2;
    mem[10'b1101011100] = 12'h1c3;
    mem[10'b1101011101] = 12'h1c3;
    mem[10'b1101011110] = 12'h1c3;
    mem[10'b1101011111] = 12'h1c4;
    mem[10'b1101100000] = 12'h1c4;
    mem[10'b1101100001] = 12'h1c4;
    mem[10'b1101100010] = 12'h1c5;
    mem[10'b1101100011] = 12'h1c5;
    mem[10'b1101100100] = 12'h1c6;
    mem[10'b1101100101] = 12'h1c6;
    mem[10'b1101100110] = 12'h1c6;
    mem[10'b1101100111] = 12'h1c7;
    mem[10'b1101101000] = 12'h1c7;
    mem[10'b1101101001] = 12'h1c8;
    mem[10'b1101101010] = 12'h1c8;
    mem[10'b1101101011] = 12'h1c8;
    mem[10'b1101101100] = 12'h1c9;
    mem[10'b1101101101] = 12'h1c9;
    mem[10'b1101101110] = 12'h1ca;
    mem[10'b1101101111] = 12'h1ca;
    mem[10'b1101110000] = 12'h1ca;
    mem[10'b1101110001] = 12'h1cb;
    mem[10'b1101110010] = 12'h1cb;
    mem[10'b1101110011] = 12'h1cc;
    mem[10'b1101110100] = 12'h1cc;
    mem[10'b1101110101] = 12'h1cc;
    mem[10'b1101110110] = 12'h1cd;
    mem[10'b1101110111] = 12'h1cd;
    mem[10'b1101111000] = 12'h1cd;
    mem[10'b1101111001] = 12'h1ce;
    mem[10'b1101111010] = 12'h1ce;
    mem[10'b1101111011] = 12'h1cf;
    mem[10'b1101111100] = 12'h1cf;
    mem[10'b1101111101] = 12'h1cf;
    mem[10'b1101111110] = 12'h1d0;
    mem[10'b1101111111] = 12'h1d0;
    mem[10'b1110000000] = 12'h1d1;
    mem[10'b1110000001] = 12'h1d1;
    mem[10'b1110000010] = 12'h1d1;
    mem[10'b1110000011] = 12'h1d2;
    mem[10'b1110000100] = 12'h1d2;
    mem[10'b1110000101] = 12'h1d2;
    mem[10'b1110000110] = 12'h1d3;
    mem[10'b1110000111] = 12'h1d3;
    mem[10'b1110001000] = 12'h1d4;
    mem[10'b1110001001] = 12'h1d4;
    mem[10'b1110001010] = 12'h1d4;
    mem[10'b1110001011] = 12'h1d5;
    mem[10'b1110001100] = 12'h1d5;
    mem[10'b1110001101] = 12'h1d6;
    mem[10'b1110001110] = 12'h1d6;
    mem[10'b1110001111] = 12'h1d6;
    mem[10'b1110010000] = 12'h1d7;
    mem[10'b1110010001] = 12'h1d7;
    mem[10'b1110010010] = 12'h1d7;
    mem[10'b1110010011] = 12'h1d8;
    mem[10'b1110010100] = 12'h1d8;
    mem[10'b1110010101] = 12'h1d9;
    mem[10'b1110010110] = 12'h1d9;
    mem[10'b1110010111] = 12'h1d9;
    mem[10'b1110011000] = 12'h1da;
    mem[10'b1110011001] = 12'h1da;
    mem[10'b1110011010] = 12'h1da;
    mem[10'b1110011011] = 12'h1db;
    mem[10'b1110011100] = 12'h1db;
    mem[10'b1110011101] = 12'h1dc;
    mem[10'b1110011110] = 12'h1dc;
    mem[10'b1110011111] = 12'h1dc;
    mem[10'b1110100000] = 12'h1dd;
    mem[10'b1110100001] = 12'h1dd;
    mem[10'b1110100010] = 12'h1dd;
    mem[10'b1110100011] = 12'h1de;
    mem[10'b1110100100] = 12'h1de;
    mem[10'b1110100101] = 12'h1df;
    mem[10'b1110100110] = 12'h1df;
    mem[10'b1110100111] = 12'h1df;
    mem[10'b1110101000] = 12'h1e0;
    mem[10'b1110101001] = 12'h1e0;
    mem[10'b1110101010] = 12'h1e1;
    mem[10'b1110101011] = 12'h1e1;
    mem[10'b1110101100] = 12'h1e1;
    mem[10'b1110101101] = 12'h1e2;
    mem[10'b1110101110] = 12'h1e2;
    mem[10'b1110101111] = 12'h1e2;
    mem[10'b1110110000] = 12'h1e3;
    mem[10'b1110110001] = 12'h1e3;
    mem[10'b1110110010] = 12'h1e4;
    mem[10'b1110110011] = 12'h1e4;
    mem[10'b1110110100] = 12'h1e4;
    mem[10'b1110110101] = 12'h1e5;
    mem[10'b1110110110] = 12'h1e5;
    mem[10'b1110110111] = 12'h1e5;
    mem[10'b1110111000] = 12'h1e6;
    mem[10'b1110111001] = 12'h1e6;
    mem[10'b1110111010] = 12'h1e6;
    mem[10'b1110111011] = 12'h1e7;
    mem[10'b1110111100] = 12'h1e7;
    mem[10'b1110111101] = 12'h1e8;
    mem[10'b1110111110] = 12'h1e8;
    mem[10'b1110111111] = 12'h1e8;
    mem[10'b1111000000] = 12'h1e9;
    mem[10'b1111000001] = 12'h1e9;
    mem[10'b1111000010] = 12'h1e9;
    mem[10'b1111000011] = 12'h1ea;
    mem[10'b1111000100] = 12'h1ea;
    mem[10'b1111000101] = 12'h1eb;
    mem[10'b1111000110] = 12'h1eb;
    mem[10'b1111000111] = 12'h1eb;
    mem[10'b1111001000] = 12'h1ec;
    mem[10'b1111001001] = 12'h1ec;
    mem[10'b1111001010] = 12'h1ec;
    mem[10'b1111001011] = 12'h1ed;
    mem[10'b1111001100] = 12'h1ed;
    mem[10'b1111001101] = 12'h1ee;
    mem[10'b1111001110] = 12'h1ee;
    mem[10'b1111001111] = 12'h1ee;
    mem[10'b1111010000] = 12'h1ef;
    mem[10'b1111010001] = 12'h1ef;
    mem[10'b1111010010] = 12'h1ef;
    mem[10'b1111010011] = 12'h1f0;
    mem[10'b1111010100] = 12'h1f0;
    mem[10'b1111010101] = 12'h1f1;
    mem[10'b1111010110] = 12'h1f1;
    mem[10'b1111010111] = 12'h1f1;
    mem[10'b1111011000] = 12'h1f2;
    mem[10'b1111011001] = 12'h1f2;
    mem[10'b1111011010] = 12'h1f2;
    mem[10'b1111011011] = 12'h1f3;
    mem[10'b1111011100] = 12'h1f3;
    mem[10'b1111011101] = 12'h1f3;
    mem[10'b1111011110] = 12'h1f4;
    mem[10'b1111011111] = 12'h1f4;
    mem[10'b1111100000] = 12'h1f5;
    mem[10'b1111100001] = 12'h1f5;
    mem[10'b1111100010] = 12'h1f5;
    mem[10'b1111100011] = 12'h1f6;
    mem[10'b1111100100] = 12'h1f6;
    mem[10'b1111100101] = 12'h1f6;
    mem[10'b1111100110] = 12'h1f7;
    mem[10'b1111100111] = 12'h1f7;
    mem[10'b1111101000] = 12'h1f7;
    mem[10'b1111101001] = 12'h1f8;
    mem[10'b1111101010] = 12'h1f8;
    mem[10'b1111101011] = 12'h1f9;
    mem[10'b1111101100] = 12'h1f9;
    mem[10'b1111101101] = 12'h1f9;
    mem[10'b1111101110] = 12'h1fa;
    mem[10'b1111101111] = 12'h1fa;
    mem[10'b1111110000] = 12'h1fa;
    mem[10'b1111110001] = 12'h1fb;
    mem[10'b1111110010] = 12'h1fb;
    mem[10'b1111110011] = 12'h1fb;
    mem[10'b1111110100] = 12'h1fc;
    mem[10'b1111110101] = 12'h1fc;
    mem[10'b1111110110] = 12'h1fd;
    mem[10'b1111110111] = 12'h1fd;
    mem[10'b1111111000] = 12'h1fd;
    mem[10'b1111111001] = 12'h1fe;
    mem[10'b1111111010] = 12'h1fe;
    mem[10'b1111111011] = 12'h1fe;
    mem[10'b1111111100] = 12'h1ff;
    mem[10'b1111111101] = 12'h1ff;
    mem[10'b1111111110] = 12'h1ff;
    mem[10'b1111111111] = 12'h200;
    end
    
    always @(posedge clock) begin
       data <= mem[address];
    end
endmodule // texture_path$unit$coords$log_m


module texture_path$unit$coords$log_r(address,clock,data);
    
    // Module arguments
    input wire  [9:0] address;
    input wire  clock;
    output reg  [11:0] data;
    
    // Update code (custom)
    reg[11:0] mem [1023:0];
    
    initial begin
    mem[10'b0] = 12'h0;
    mem[10'b1] = 12'h1;
    mem[10'b10] = 12'h2;
    mem[10'b11] = 12'h3;
    mem[10'b100] = 12'h3;
    mem[10'b101] = 12'h4;
    mem[10'b110] = 12'h5;
    mem[10'b111] = 12'h5;
    mem[10'b1000] = 12'h6;
    mem[10'b1001] = 12'h7;
    mem[10'b1010] = 12'h8;
    mem[10'b1011] = 12'h8;
    mem[10'b1100] = 12'h9;
    mem[10'b1101] = 12'ha;
    mem[10'b1110] = 12'ha;
    mem[10'b1111] = 12'hb;
    mem[10'b10000] = 12'hc;
    mem[10'b10001] = 12'hd;
    mem[10'b10010] = 12'hd;
    mem[10'b10011] = 12'he;
    mem[10'b10100] = 12'hf;
    mem[10'b10101] = 12'hf;
    mem[10'b10110] = 12'h10;
    mem[10'b10111] = 12'h11;
    mem[10'b11000] = 12'h11;
    mem[10'b11001] = 12'h12;
    mem[10'b11010] = 12'h13;
    mem[10'b11011] = 12'h14;
    mem[10'b11100] = 12'h14;
    mem[10'b11101] = 12'h15;
    mem[10'b11110] = 12'h16;
    mem[10'b11111] = 12'h16;
    mem[10'b100000] = 12'h17;
    mem[10'b100001] = 12'h18;
    mem[10'b100010] = 12'h18;
    mem[10'b100011] = 12'h19;
    mem[10'b100100] = 12'h1a;
    mem[10'b100101] = 12'h1b;
    mem[10'b100110] = 12'h1b;
    mem[10'b100111] = 12'h1c;
    mem[10'b101000] = 12'h1d;
    mem[10'b101001] = 12'h1d;
    mem[10'b101010] = 12'h1e;
    mem[10'b101011] = 12'h1f;
    mem[10'b101100] = 12'h1f;
    mem[10'b101101] = 12'h20;
    mem[10'b101110] = 12'h21;
    mem[10'b101111] = 12'h21;
    mem[10'b110000] = 12'h22;
    mem[10'b110001] = 12'h23;
    mem[10'b110010] = 12'h24;
    mem[10'b110011] = 12'h24;
    mem[10'b110100] = 12'h25;
    mem[10'b110101] = 12'h26;
    mem[10'b110110] = 12'h26;
    mem[10'b110111] = 12'h27;
    mem[10'b111000] = 12'h28;
    mem[10'b111001] = 12'h28;
    mem[10'b111010] = 12'h29;
    mem[10'b111011] = 12'h2a;
    mem[10'b111100] = 12'h2a;
    mem[10'b111101] = 12'h2b;
    mem[10'b111110] = 12'h2c;
    mem[10'b111111] = 12'h2c;
    mem[10'b1000000] = 12'h2d;
    mem[10'b1000001] = 12'h2e;
    mem[10'b1000010] = 12'h2e;
    mem[10'b1000011] = 12'h2f;
    mem[10'b1000100] = 12'h30;
    mem[10'b1000101] = 12'h31;
    mem[10'b1000110] = 12'h31;
    mem[10'b1000111] = 12'h32;
    mem[10'b1001000] = 12'h33;
    mem[10'b1001001] = 12'h33;
    mem[10'b1001010] = 12'h34;
    mem[10'b1001011] = 12'h35;
    mem[10'b1001100] = 12'h35;
    mem[10'b1001101] = 12'h36;
    mem[10'b1001110] = 12'h37;
    mem[10'b1001111] = 12'h37;
    mem[10'b1010000] = 12'h38;
    mem[10'b1010001] = 12'h39;
    mem[10'b1010010] = 12'h39;
    mem[10'b1010011] = 12'h3a;
    mem[10'b1010100] = 12'h3b;
    mem[10'b1010101] = 12'h3b;
    mem[10'b1010110] = 12'h3c;
    mem[10'b1010111] = 12'h3d;
    mem[10'b1011000] = 12'h3d;
    mem[10'b1011001] = 12'h3e;
    mem[10'b1011010] = 12'h3f;
    mem[10'b1011011] = 12'h3f;
    mem[10'b1011100] = 12'h40;
    mem[10'b1011101] = 12'h41;
    mem[10'b1011110] = 12'h41;
    mem[10'b1011111] = 12'h42;
    mem[10'b1100000] = 12'h43;
    mem[10'b1100001] = 12'h43;
    mem[10'b1100010] = 12'h44;
    mem[10'b1100011] = 12'h44;
    mem[10'b1100100] = 12'h45;
    mem[10'b1100101] = 12'h46;
    mem[10'b1100110] = 12'h46;
    mem[10'b1100111] = 12'h47;
    mem[10'b1101000] = 12'h48;
    mem[10'b1101001] = 12'h48;
    mem[10'b1101010] = 12'h49;
    mem[10'b1101011] = 12'h4a;
    mem[10'b1101100] = 12'h4a;
    mem[10'b1101101] = 12'h4b;
    mem[10'b1101110] = 12'h4c;
    mem[10'b1101111] = 12'h4c;
    mem[10'b1110000] = 12'h4d;
    mem[10'b1110001] = 12'h4e;
    mem[10'b1110010] = 12'h4e;
    mem[10'b1110011] = 12'h4f;
    mem[10'b1110100] = 12'h50;
    mem[10'b1110101] = 12'h50;
    mem[10'b1110110] = 12'h51;
    mem[10'b1110111] = 12'h52;
    mem[10'b1111000] = 12'h52;
    mem[10'b1111001] = 12'h53;
    mem[10'b1111010] = 12'h53;
    mem[10'b1111011] = 12'h54;
    mem[10'b1111100] = 12'h55;
    mem[10'b1111101] = 12'h55;
    mem[10'b1111110] = 12'h56;
    mem[10'b1111111] = 12'h57;
    mem[10'b10000000] = 12'h57;
    mem[10'b10000001] = 12'h58;
    mem[10'b10000010] = 12'h59;
    mem[10'b10000011] = 12'h59;
    mem[10'b10000100] = 12'h5a;
    mem[10'b10000101] = 12'h5b;
    mem[10'b10000110] = 12'h5b;
    mem[10'b10000111] = 12'h5c;
    mem[10'b10001000] = 12'h5c;
    mem[10'b10001001] = 12'h5d;
    mem[10'b10001010] = 12'h5e;
    mem[10'b10001011] = 12'h5e;
    mem[10'b10001100] = 12'h5f;
    mem[10'b10001101] = 12'h60;
    mem[10'b10001110] = 12'h60;
    mem[10'b10001111] = 12'h61;
    mem[10'b10010000] = 12'h62;
    mem[10'b10010001] = 12'h62;
    mem[10'b10010010] = 12'h63;
    mem[10'b10010011] = 12'h63;
    mem[10'b10010100] = 12'h64;
    mem[10'b10010101] = 12'h65;
    mem[10'b10010110] = 12'h65;
    mem[10'b10010111] = 12'h66;
    mem[10'b10011000] = 12'h67;
    mem[10'b10011001] = 12'h67;
    mem[10'b10011010] = 12'h68;
    mem[10'b10011011] = 12'h68;
    mem[10'b10011100] = 12'h69;
    mem[10'b10011101] = 12'h6a;
    mem[10'b10011110] = 12'h6a;
    mem[10'b10011111] = 12'h6b;
    mem[10'b10100000] = 12'h6c;
    mem[10'b10100001] = 12'h6c;
    mem[10'b10100010] = 12'h6d;
    mem[10'b10100011] = 12'h6d;
    mem[10'b10100100] = 12'h6e;
    mem[10'b10100101] = 12'h6f;
    mem[10'b10100110] = 12'h6f;
    mem[10'b10100111] = 12'h70;
    mem[10'b10101000] = 12'h71;
    mem[10'b10101001] = 12'h71;
    mem[10'b10101010] = 12'h72;
    mem[10'b10101011] = 12'h72;
    mem[10'b10101100] = 12'h73;
    mem[10'b10101101] = 12'h74;
    mem[10'b10101110] = 12'h74;
    mem[10'b10101111] = 12'h75;
    mem[10'b10110000] = 12'h75;
    mem[10'b10110001] = 12'h76;
    mem[10'b10110010] = 12'h77;
    mem[10'b10110011] = 12'h77;
    mem[10'b10110100] = 12'h78;
    mem[10'b10110101] = 12'h79;
    mem[10'b10110110] = 12'h79;
    mem[10'b10110111] = 12'h7a;
    mem[10'b10111000] = 12'h7a;
    mem[10'b10111001] = 12'h7b;
    mem[10'b10111010] = 12'h7c;
    mem[10'b10111011] = 12'h7c;
    mem[10'b10111100] = 12'h7d;
    mem[10'b10111101] = 12'h7d;
    mem[10'b10111110] = 12'h7e;
    mem[10'b10111111] = 12'h7f;
    mem[10'b11000000] = 12'h7f;
    mem[10'b11000001] = 12'h80;
    mem[10'b11000010] = 12'h80;
    mem[10'b11000011] = 12'h81;
    mem[10'b11000100] = 12'h82;
    mem[10'b11000101] = 12'h82;
    mem[10'b11000110] = 12'h83;
    mem[10'b11000111] = 12'h83;
    mem[10'b11001000] = 12'h84;
    mem[10'b11001001] = 12'h85;
    mem[10'b11001010] = 12'h85;
    mem[10'b11001011] = 12'h86;
    mem[10'b11001100] = 12'h86;
    mem[10'b11001101] = 12'h87;
    mem[10'b11001110] = 12'h88;
    mem[10'b11001111] = 12'h88;
    mem[10'b11010000] = 12'h89;
    mem[10'b11010001] = 12'h89;
    mem[10'b11010010] = 12'h8a;
    mem[10'b11010011] = 12'h8b;
    mem[10'b11010100] = 12'h8b;
    mem[10'b11010101] = 12'h8c;
    mem[10'b11010110] = 12'h8c;
    mem[10'b11010111] = 12'h8d;
    mem[10'b11011000] = 12'h8e;
    mem[10'b11011001] = 12'h8e;
    mem[10'b11011010] = 12'h8f;
    mem[10'b11011011] = 12'h8f;
    mem[10'b11011100] = 12'h90;
    mem[10'b11011101] = 12'h91;
    mem[10'b11011110] = 12'h91;
    mem[10'b11011111] = 12'h92;
    mem[10'b11100000] = 12'h92;
    mem[10'b11100001] = 12'h93;
    mem[10'b11100010] = 12'h94;
    mem[10'b11100011] = 12'h94;
    mem[10'b11100100] = 12'h95;
    mem[10'b11100101] = 12'h95;
    mem[10'b11100110] = 12'h96;
    mem[10'b11100111] = 12'h97;
    mem[10'b11101000] = 12'h97;
    mem[10'b11101001] = 12'h98;
    mem[10'b11101010] = 12'h98;
    mem[10'b11101011] = 12'h99;
    mem[10'b11101100] = 12'h99;
    mem[10'b11101101] = 12'h9a;
    mem[10'b11101110] = 12'h9b;
    mem[10'b11101111] = 12'h9b;
    mem[10'b11110000] = 12'h9c;
    mem[10'b11110001] = 12'h9c;
    mem[10'b11110010] = 12'h9d;
    mem[10'b11110011] = 12'h9e;
    mem[10'b11110100] = 12'h9e;
    mem[10'b11110101] = 12'h9f;
    mem[10'b11110110] = 12'h9f;
    mem[10'b11110111] = 12'ha0;
    mem[10'b11111000] = 12'ha0;
    mem[10'b11111001] = 12'ha1;
    mem[10'b11111010] = 12'ha2;
    mem[10'b11111011] = 12'ha2;
    mem[10'b11111100] = 12'ha3;
    mem[10'b11111101] = 12'ha3;
    mem[10'b11111110] = 12'ha4;
    mem[10'b11111111] = 12'ha5;
    mem[10'b100000000] = 12'ha5;
    mem[10'b100000001] = 12'ha6;
    mem[10'b100000010] = 12'ha6;
    mem[10'b100000011] = 12'ha7;
    mem[10'b100000100] = 12'ha7;
    mem[10'b100000101] = 12'ha8;
    mem[10'b100000110] = 12'ha9;
    mem[10'b100000111] = 12'ha9;
    mem[10'b100001000] = 12'haa;
    mem[10'b100001001] = 12'haa;
    mem[10'b100001010] = 12'hab;
    mem[10'b100001011] = 12'hab;
    mem[10'b100001100] = 12'hac;
    mem[10'b100001101] = 12'had;
    mem[10'b100001110] = 12'had;
    mem[10'b100001111] = 12'hae;
    mem[10'b100010000] = 12'hae;
    mem[10'b100010001] = 12'haf;
    mem[10'b100010010] = 12'haf;
    mem[10'b100010011] = 12'hb0;
    mem[10'b100010100] = 12'hb1;
    mem[10'b100010101] = 12'hb1;
    mem[10'b100010110] = 12'hb2;
    mem[10'b100010111] = 12'hb2;
    mem[10'b100011000] = 12'hb3;
    mem[10'b100011001] = 12'hb3;
    mem[10'b100011010] = 12'hb4;
    mem[10'b100011011] = 12'hb5;
    mem[10'b100011100] = 12'hb5;
    mem[10'b100011101] = 12'hb6;
    mem[10'b100011110] = 12'hb6;
    mem[10'b100011111] = 12'hb7;
    mem[10'b100100000] = 12'hb7;
    mem[10'b100100001] = 12'hb8;
    mem[10'b100100010] = 12'hb8;
    mem[10'b100100011] = 12'hb9;
    mem[10'b100100100] = 12'hba;
    mem[10'b100100101] = 12'hba;
    mem[10'b100100110] = 12'hbb;
    mem[10'b100100111] = 12'hbb;
    mem[10'b100101000] = 12'hbc;
    mem[10'b100101001] = 12'hbc;
    mem[10'b100101010] = 12'hbd;
    mem[10'b100101011] = 12'hbe;
    mem[10'b100101100] = 12'hbe;
    mem[10'b100101101] = 12'hbf;
    mem[10'b100101110] = 12'hbf;
    mem[10'b100101111] = 12'hc0;
    mem[10'b100110000] = 12'hc0;
    mem[10'b100110001] = 12'hc1;
    mem[10'b100110010] = 12'hc1;
    mem[10'b100110011] = 12'hc2;
    mem[10'b100110100] = 12'hc3;
    mem[10'b100110101] = 12'hc3;
    mem[10'b100110110] = 12'hc4;
    mem[10'b100110111] = 12'hc4;
    mem[10'b100111000] = 12'hc5;
    mem[10'b100111001] = 12'hc5;
    mem[10'b100111010] = 12'hc6;
    mem[10'b100111011] = 12'hc6;
    mem[10'b100111100] = 12'hc7;
    mem[10'b100111101] = 12'hc7;
    mem[10'b100111110] = 12'hc8;
    mem[10'b100111111] = 12'hc9;
    mem[10'b101000000] = 12'hc9;
    mem[10'b101000001] = 12'hca;
    mem[10'b101000010] = 12'hca;
    mem[10'b101000011] = 12'hcb;
    mem[10'b101000100] = 12'hcb;
    mem[10'b101000101] = 12'hcc;
    mem[10'b101000110] = 12'hcc;
    mem[10'b101000111] = 12'hcd;
    mem[10'b101001000] = 12'hce;
    mem[10'b101001001] = 12'hce;
    mem[10'b101001010] = 12'hcf;
    mem[10'b101001011] = 12'hcf;
    mem[10'b101001100] = 12'hd0;
    mem[10'b101001101] = 12'hd0;
    mem[10'b101001110] = 12'hd1;
    mem[10'b101001111] = 12'hd1;
    mem[10'b101010000] = 12'hd2;
    mem[10'b101010001] = 12'hd2;
    mem[10'b101010010] = 12'hd3;
    mem[10'b101010011] = 12'hd4;
    mem[10'b101010100] = 12'hd4;
    mem[10'b101010101] = 12'hd5;
    mem[10'b101010110] = 12'hd5;
    mem[10'b101010111] = 12'hd6;
    mem[10'b101011000] = 12'hd6;
    mem[10'b101011001] = 12'hd7;
    mem[10'b101011010] = 12'hd7;
    mem[10'b101011011] = 12'hd8;
    mem[10'b101011100] = 12'hd8;
    mem[10'b101011101] = 12'hd9;
    mem[10'b101011110] = 12'hd9;
    mem[10'b101011111] = 12'hda;
    mem[10'b101100000] = 12'hdb;
    mem[10'b101100001] = 12'hdb;
    mem[10'b101100010] = 12'hdc;
    mem[10'b101100011] = 12'hdc;
    mem[10'b101100100] = 12'hdd;
    mem[10'b101100101] = 12'hdd;
    mem[10'b101100110] = 12'hde;
    mem[10'b101100111] = 12'hde;
    mem[10'b101101000] = 12'hdf;
    mem[10'b101101001] = 12'hdf;
    mem[10'b101101010] = 12'he0;
    mem[10'b101101011] = 12'he0;
    mem[10'b101101100] = 12'he1;
    mem[10'b101101101] = 12'he1;
    mem[10'b101101110] = 12'he2;
    mem[10'b101101111] = 12'he3;
    mem[10'b101110000] = 12'he3;
    mem[10'b101110001] = 12'he4;
    mem[10'b101110010] = 12'he4;
    mem[10'b101110011] = 12'he5;
    mem[10'b101110100] = 12'he5;
    mem[10'b101110101] = 12'he6;
    mem[10'b101110110] = 12'he6;
    mem[10'b101110111] = 12'he7;
    mem[10'b101111000] = 12'he7;
    mem[10'b101111001] = 12'he8;
    mem[10'b101111010] = 12'he8;
    mem[10'b101111011] = 12'he9;
    mem[10'b101111100] = 12'he9;
    mem[10'b101111101] = 12'hea;
    mem[10'b101111110] = 12'hea;
    mem[10'b101111111] = 12'heb;
    mem[10'b110000000] = 12'heb;
    mem[10'b110000001] = 12'hec;
    mem[10'b110000010] = 12'hed;
    mem[10'b110000011] = 12'hed;
    mem[10'b110000100] = 12'hee;
    mem[10'b110000101] = 12'hee;
    mem[10'b110000110] = 12'hef;
    mem[10'b110000111] = 12'hef;
    mem[10'b110001000] = 12'hf0;
    mem[10'b110001001] = 12'hf0;
    mem[10'b110001010] = 12'hf1;
    mem[10'b110001011] = 12'hf1;
    mem[10'b110001100] = 12'hf2;
    mem[10'b110001101] = 12'hf2;
    mem[10'b110001110] = 12'hf3;
    mem[10'b110001111] = 12'hf3;
    mem[10'b110010000] = 12'hf4;
    mem[10'b110010001] = 12'hf4;
    mem[10'b110010010] = 12'hf5;
    mem[10'b110010011] = 12'hf5;
    mem[10'b110010100] = 12'hf6;
    mem[10'b110010101] = 12'hf6;
    mem[10'b110010110] = 12'hf7;
    mem[10'b110010111] = 12'hf7;
    mem[10'b110011000] = 12'hf8;
    mem[10'b110011001] = 12'hf8;
    mem[10'b110011010] = 12'hf9;
    mem[10'b110011011] = 12'hfa;
    mem[10'b110011100] = 12'hfa;
    mem[10'b110011101] = 12'hfb;
    mem[10'b110011110] = 12'hfb;
    mem[10'b110011111] = 12'hfc;
    mem[10'b110100000] = 12'hfc;
    mem[10'b110100001] = 12'hfd;
    mem[10'b110100010] = 12'hfd;
    mem[10'b110100011] = 12'hfe;
    mem[10'b110100100] = 12'hfe;
    mem[10'b110100101] = 12'hff;
    mem[10'b110100110] = 12'hff;
    mem[10'b110100111] = 12'h100;
    mem[10'b110101000] = 12'h100;
    mem[10'b110101001] = 12'h101;
    mem[10'b110101010] = 12'h101;
    mem[10'b110101011] = 12'h102;
    mem[10'b110101100] = 12'h102;
    mem[10'b110101101] = 12'h103;
    mem[10'b110101110] = 12'h103;
    mem[10'b110101111] = 12'h104;
    mem[10'b110110000] = 12'h104;
    mem[10'b110110001] = 12'h105;
    mem[10'b110110010] = 12'h105;
    mem[10'b110110011] = 12'h106;
    mem[10'b110110100] = 12'h106;
    mem[10'b110110101] = 12'h107;
    mem[10'b110110110] = 12'h107;
    mem[10'b110110111] = 12'h108;
    mem[10'b110111000] = 12'h108;
    mem[10'b110111001] = 12'h109;
    mem[10'b110111010] = 12'h109;
    mem[10'b110111011] = 12'h10a;
    mem[10'b110111100] = 12'h10a;
    mem[10'b110111101] = 12'h10b;
    mem[10'b110111110] = 12'h10b;
    mem[10'b110111111] = 12'h10c;
    mem[10'b111000000] = 12'h10c;
    mem[10'b111000001] = 12'h10d;
    mem[10'b111000010] = 12'h10d;
    mem[10'b111000011] = 12'h10e;
    mem[10'b111000100] = 12'h10e;
    mem[10'b111000101] = 12'h10f;
    mem[10'b111000110] = 12'h10f;
    mem[10'b111000111] = 12'h110;
    mem[10'b111001000] = 12'h110;
    mem[10'b111001001] = 12'h111;
    mem[10'b111001010] = 12'h111;
    mem[10'b111001011] = 12'h112;
    mem[10'b111001100] = 12'h112;
    mem[10'b111001101] = 12'h113;
    mem[10'b111001110] = 12'h113;
    mem[10'b111001111] = 12'h114;
    mem[10'b111010000] = 12'h114;
    mem[10'b111010001] = 12'h115;
    mem[10'b111010010] = 12'h115;
    mem[10'b111010011] = 12'h116;
    mem[10'b111010100] = 12'h116;
    mem[10'b111010101] = 12'h117;
    mem[10'b111010110] = 12'h117;
    mem[10'b111010111] = 12'h118;
    mem[10'b111011000] = 12'h118;
    mem[10'b111011001] = 12'h119;
    mem[10'b111011010] = 12'h119;
    mem[10'b111011011] = 12'h11a;
    mem[10'b111011100] = 12'h11a;
    mem[10'b111011101] = 12'h11b;
    mem[10'b111011110] = 12'h11b;
    mem[10'b111011111] = 12'h11c;
    mem[10'b111100000] = 12'h11c;
    mem[10'b111100001] = 12'h11d;
    mem[10'b111100010] = 12'h11d;
    mem[10'b111100011] = 12'h11e;
    mem[10'b111100100] = 12'h11e;
    mem[10'b111100101] = 12'h11f;
    mem[10'b111100110] = 12'h11f;
    mem[10'b111100111] = 12'h120;
    mem[10'b111101000] = 12'h120;
    mem[10'b111101001] = 12'h121;
    mem[10'b111101010] = 12'h121;
    mem[10'b111101011] = 12'h122;
    mem[10'b111101100] = 12'h122;
    mem[10'b111101101] = 12'h123;
    mem[10'b111101110] = 12'h123;
    mem[10'b111101111] = 12'h124;
    mem[10'b111110000] = 12'h124;
    mem[10'b111110001] = 12'h124;
    mem[10'b111110010] = 12'h125;
    mem[10'b111110011] = 12'h125;
    mem[10'b111110100] = 12'h126;
    mem[10'b111110101] = 12'h126;
    mem[10'b111110110] = 12'h127;
    mem[10'b111110111] = 12'h127;
    mem[10'b111111000] = 12'h128;
    mem[10'b111111001] = 12'h128;
    mem[10'b111111010] = 12'h129;
    mem[10'b111111011] = 12'h129;
    mem[10'b111111100] = 12'h12a;
    mem[10'b111111101] = 12'h12a;
    mem[10'b111111110] = 12'h12b;
    mem[10'b111111111] = 12'h12b;
    mem[10'b1000000000] = 12'h12c;
    mem[10'b1000000001] = 12'h12c;
    mem[10'b1000000010] = 12'h12d;
    mem[10'b1000000011] = 12'h12d;
    mem[10'b1000000100] = 12'h12e;
    mem[10'b1000000101] = 12'h12e;
    mem[10'b1000000110] = 12'h12f;
    mem[10'b1000000111] = 12'h12f;
    mem[10'b1000001000] = 12'h130;
    mem[10'b1000001001] = 12'h130;
    mem[10'b1000001010] = 12'h131;
    mem[10'b1000001011] = 12'h131;
    mem[10'b1000001100] = 12'h131;
    mem[10'b1000001101] = 12'h132;
    mem[10'b1000001110] = 12'h132;
    mem[10'b1000001111] = 12'h133;
    mem[10'b1000010000] = 12'h133;
    mem[10'b1000010001] = 12'h134;
    mem[10'b1000010010] = 12'h134;
    mem[10'b1000010011] = 12'h135;
    mem[10'b1000010100] = 12'h135;
    mem[10'b1000010101] = 12'h136;
    mem[10'b1000010110] = 12'h136;
    mem[10'b1000010111] = 12'h137;
    mem[10'b1000011000] = 12'h137;
    mem[10'b1000011001] = 12'h138;
    mem[10'b1000011010] = 12'h138;
    mem[10'b1000011011] = 12'h139;
    mem[10'b1000011100] = 12'h139;
    mem[10'b1000011101] = 12'h13a;
    mem[10'b1000011110] = 12'h13a;
    mem[10'b1000011111] = 12'h13a;
    mem[10'b1000100000] = 12'h13b;
    mem[10'b1000100001] = 12'h13b;
    mem[10'b1000100010] = 12'h13c;
    mem[10'b1000100011] = 12'h13c;
    mem[10'b1000100100] = 12'h13d;
    mem[10'b1000100101] = 12'h13d;
    mem[10'b1000100110] = 12'h13e;
    mem[10'b1000100111] = 12'h13e;
    mem[10'b1000101000] = 12'h13f;
    mem[10'b1000101001] = 12'h13f;
    mem[10'b1000101010] = 12'h140;
    mem[10'b1000101011] = 12'h140;
    mem[10'b1000101100] = 12'h141;
    mem[10'b1000101101] = 12'h141;
    mem[10'b1000101110] = 12'h142;
    mem[10'b1000101111] = 12'h142;
    mem[10'b1000110000] = 12'h142;
    mem[10'b1000110001] = 12'h143;
    mem[10'b1000110010] = 12'h143;
    mem[10'b1000110011] = 12'h144;
    mem[10'b1000110100] = 12'h144;
    mem[10'b1000110101] = 12'h145;
    mem[10'b1000110110] = 12'h145;
    mem[10'b1000110111] = 12'h146;
    mem[10'b1000111000] = 12'h146;
    mem[10'b1000111001] = 12'h147;
    mem[10'b1000111010] = 12'h147;
    mem[10'b1000111011] = 12'h148;
    mem[10'b1000111100] = 12'h148;
    mem[10'b1000111101] = 12'h148;
    mem[10'b1000111110] = 12'h149;
    mem[10'b1000111111] = 12'h149;
    mem[10'b1001000000] = 12'h14a;
    mem[10'b1001000001] = 12'h14a;
    mem[10'b1001000010] = 12'h14b;
    mem[10'b1001000011] = 12'h14b;
    mem[10'b1001000100] = 12'h14c;
    mem[10'b1001000101] = 12'h14c;
    mem[10'b1001000110] = 12'h14d;
    mem[10'b1001000111] = 12'h14d;
    mem[10'b1001001000] = 12'h14e;
    mem[10'b1001001001] = 12'h14e;
    mem[10'b1001001010] = 12'h14e;
    mem[10'b1001001011] = 12'h14f;
    mem[10'b1001001100] = 12'h14f;
    mem[10'b1001001101] = 12'h150;
    mem[10'b1001001110] = 12'h150;
    mem[10'b1001001111] = 12'h151;
    mem[10'b1001010000] = 12'h151;
    mem[10'b1001010001] = 12'h152;
    mem[10'b1001010010] = 12'h152;
    mem[10'b1001010011] = 12'h153;
    mem[10'b1001010100] = 12'h153;
    mem[10'b1001010101] = 12'h154;
    mem[10'b1001010110] = 12'h154;
    mem[10'b1001010111] = 12'h154;
    mem[10'b1001011000] = 12'h155;
    mem[10'b1001011001] = 12'h155;
    mem[10'b1001011010] = 12'h156;
    mem[10'b1001011011] = 12'h156;
    mem[10'b1001011100] = 12'h157;
    mem[10'b1001011101] = 12'h157;
    mem[10'b1001011110] = 12'h158;
    mem[10'b1001011111] = 12'h158;
    mem[10'b1001100000] = 12'h159;
    mem[10'b1001100001] = 12'h159;
    mem[10'b1001100010] = 12'h159;
    mem[10'b1001100011] = 12'h15a;
    mem[10'b1001100100] = 12'h15a;
    mem[10'b1001100101] = 12'h15b;
    mem[10'b1001100110] = 12'h15b;
    mem[10'b1001100111] = 12'h15c;
    mem[10'b1001101000] = 12'h15c;
    mem[10'b1001101001] = 12'h15d;
    mem[10'b1001101010] = 12'h15d;
    mem[10'b1001101011] = 12'h15d;
    mem[10'b1001101100] = 12'h15e;
    mem[10'b1001101101] = 12'h15e;
    mem[10'b1001101110] = 12'h15f;
    mem[10'b1001101111] = 12'h15f;
    mem[10'b1001110000] = 12'h160;
    mem[10'b1001110001] = 12'h160;
    mem[10'b1001110010] = 12'h161;
    mem[10'b1001110011] = 12'h161;
    mem[10'b1001110100] = 12'h162;
    mem[10'b1001110101] = 12'h162;
    mem[10'b1001110110] = 12'h162;
    mem[10'b1001110111] = 12'h163;
    mem[10'b1001111000] = 12'h163;
    mem[10'b1001111001] = 12'h164;
    mem[10'b1001111010] = 12'h164;
    mem[10'b1001111011] = 12'h165;
    mem[10'b1001111100] = 12'h165;
    mem[10'b1001111101] = 12'h166;
    mem[10'b1001111110] = 12'h166;
    mem[10'b1001111111] = 12'h166;
    mem[10'b1010000000] = 12'h167;
    mem[10'b1010000001] = 12'h167;
    mem[10'b1010000010] = 12'h168;
    mem[10'b1010000011] = 12'h168;
    mem[10'b1010000100] = 12'h169;
    mem[10'b1010000101] = 12'h169;
    mem[10'b1010000110] = 12'h16a;
    mem[10'b1010000111] = 12'h16a;
    mem[10'b1010001000] = 12'h16a;
    mem[10'b1010001001] = 12'h16b;
    mem[10'b1010001010] = 12'h16b;
    mem[10'b1010001011] = 12'h16c;
    mem[10'b1010001100] = 12'h16c;
    mem[10'b1010001101] = 12'h16d;
    mem[10'b1010001110] = 12'h16d;
    mem[10'b1010001111] = 12'h16d;
    mem[10'b1010010000] = 12'h16e;
    mem[10'b1010010001] = 12'h16e;
    mem[10'b1010010010] = 12'h16f;
    mem[10'b1010010011] = 12'h16f;
    mem[10'b1010010100] = 12'h170;
    mem[10'b1010010101] = 12'h170;
    mem[10'b1010010110] = 12'h171;
    mem[10'b1010010111] = 12'h171;
    mem[10'b1010011000] = 12'h171;
    mem[10'b1010011001] = 12'h172;
    mem[10'b1010011010] = 12'h172;
    mem[10'b1010011011] = 12'h173;
    mem[10'b1010011100] = 12'h173;
    mem[10'b1010011101] = 12'h174;
    mem[10'b1010011110] = 12'h174;
    mem[10'b1010011111] = 12'h174;
    mem[10'b1010100000] = 12'h175;
    mem[10'b1010100001] = 12'h175;
    mem[10'b1010100010] = 12'h176;
    mem[10'b1010100011] = 12'h176;
    mem[10'b1010100100] = 12'h177;
    mem[10'b1010100101] = 12'h177;
    mem[10'b1010100110] = 12'h178;
    mem[10'b1010100111] = 12'h178;
    mem[10'b1010101000] = 12'h178;
    mem[10'b1010101001] = 12'h179;
    mem[10'b1010101010] = 12'h179;
    mem[10'b1010101011] = 12'h17a;
    mem[10'b1010101100] = 12'h17a;
    mem[10'b1010101101] = 12'h17b;
    mem[10'b1010101110] = 12'h17b;
    mem[10'b1010101111] = 12'h17b;
    mem[10'b1010110000] = 12'h17c;
    mem[10'b1010110001] = 12'h17c;
    mem[10'b1010110010] = 12'h17d;
    mem[10'b1010110011] = 12'h17d;
    mem[10'b1010110100] = 12'h17e;
    mem[10'b1010110101] = 12'h17e;
    mem[10'b1010110110] = 12'h17e;
    mem[10'b1010110111] = 12'h17f;
    mem[10'b1010111000] = 12'h17f;
    mem[10'b1010111001] = 12'h180;
    mem[10'b1010111010] = 12'h180;
    mem[10'b1010111011] = 12'h181;
    mem[10'b1010111100] = 12'h181;
    mem[10'b1010111101] = 12'h181;
    mem[10'b1010111110] = 12'h182;
    mem[10'b1010111111] = 12'h182;
    mem[10'b1011000000] = 12'h183;
    mem[10'b1011000001] = 12'h183;
    mem[10'b1011000010] = 12'h184;
    mem[10'b1011000011] = 12'h184;
    mem[10'b1011000100] = 12'h184;
    mem[10'b1011000101] = 12'h185;
    mem[10'b1011000110] = 12'h185;
    mem[10'b1011000111] = 12'h186;
    mem[10'b1011001000] = 12'h186;
    mem[10'b1011001001] = 12'h187;
    mem[10'b1011001010] = 12'h187;
    mem[10'b1011001011] = 12'h187;
    mem[10'b1011001100] = 12'h188;
    mem[10'b1011001101] = 12'h188;
    mem[10'b1011001110] = 12'h189;
    mem[10'b1011001111] = 12'h189;
    mem[10'b1011010000] = 12'h18a;
    mem[10'b1011010001] = 12'h18a;
    mem[10'b1011010010] = 12'h18a;
    mem[10'b1011010011] = 12'h18b;
    mem[10'b1011010100] = 12'h18b;
    mem[10'b1011010101] = 12'h18c;
    mem[10'b1011010110] = 12'h18c;
    mem[10'b1011010111] = 12'h18c;
    mem[10'b1011011000] = 12'h18d;
    mem[10'b1011011001] = 12'h18d;
    mem[10'b1011011010] = 12'h18e;
    mem[10'b1011011011] = 12'h18e;
    mem[10'b1011011100] = 12'h18f;
    mem[10'b1011011101] = 12'h18f;
    mem[10'b1011011110] = 12'h18f;
    mem[10'b1011011111] = 12'h190;
    mem[10'b1011100000] = 12'h190;
    mem[10'b1011100001] = 12'h191;
    mem[10'b1011100010] = 12'h191;
    mem[10'b1011100011] = 12'h192;
    mem[10'b1011100100] = 12'h192;
    mem[10'b1011100101] = 12'h192;
    mem[10'b1011100110] = 12'h193;
    mem[10'b1011100111] = 12'h193;
    mem[10'b1011101000] = 12'h194;
    mem[10'b1011101001] = 12'h194;
    mem[10'b1011101010] = 12'h194;
    mem[10'b1011101011] = 12'h195;
    mem[10'b1011101100] = 12'h195;
    mem[10'b1011101101] = 12'h196;
    mem[10'b1011101110] = 12'h196;
    mem[10'b1011101111] = 12'h197;
    mem[10'b1011110000] = 12'h197;
    mem[10'b1011110001] = 12'h197;
    mem[10'b1011110010] = 12'h198;
    mem[10'b1011110011] = 12'h198;
    mem[10'b1011110100] = 12'h199;
    mem[10'b1011110101] = 12'h199;
    mem[10'b1011110110] = 12'h199;
    mem[10'b1011110111] = 12'h19a;
    mem[10'b1011111000] = 12'h19a;
    mem[10'b1011111001] = 12'h19b;
    mem[10'b1011111010] = 12'h19b;
    mem[10'b1011111011] = 12'h19c;
    mem[10'b1011111100] = 12'h19c;
    mem[10'b1011111101] = 12'h19c;
    mem[10'b1011111110] = 12'h19d;
    mem[10'b1011111111] = 12'h19d;
    mem[10'b1100000000] = 12'h19e;
    mem[10'b1100000001] = 12'h19e;
    mem[10'b1100000010] = 12'h19e;
    mem[10'b1100000011] = 12'h19f;
    mem[10'b1100000100] = 12'h19f;
    mem[10'b1100000101] = 12'h1a0;
    mem[10'b1100000110] = 12'h1a0;
    mem[10'b1100000111] = 12'h1a0;
    mem[10'b1100001000] = 12'h1a1;
    mem[10'b1100001001] = 12'h1a1;
    mem[10'b1100001010] = 12'h1a2;
    mem[10'b1100001011] = 12'h1a2;
    mem[10'b1100001100] = 12'h1a3;
    mem[10'b1100001101] = 12'h1a3;
    mem[10'b1100001110] = 12'h1a3;
    mem[10'b1100001111] = 12'h1a4;
    mem[10'b1100010000] = 12'h1a4;
    mem[10'b1100010001] = 12'h1a5;
    mem[10'b1100010010] = 12'h1a5;
    mem[10'b1100010011] = 12'h1a5;
    mem[10'b1100010100] = 12'h1a6;
    mem[10'b1100010101] = 12'h1a6;
    mem[10'b1100010110] = 12'h1a7;
    mem[10'b1100010111] = 12'h1a7;
    mem[10'b1100011000] = 12'h1a7;
    mem[10'b1100011001] = 12'h1a8;
    mem[10'b1100011010] = 12'h1a8;
    mem[10'b1100011011] = 12'h1a9;
    mem[10'b1100011100] = 12'h1a9;
    mem[10'b1100011101] = 12'h1a9;
    mem[10'b1100011110] = 12'h1aa;
    mem[10'b1100011111] = 12'h1aa;
    mem[10'b1100100000] = 12'h1ab;
    mem[10'b1100100001] = 12'h1ab;
    mem[10'b1100100010] = 12'h1ab;
    mem[10'b1100100011] = 12'h1ac;
    mem[10'b1100100100] = 12'h1ac;
    mem[10'b1100100101] = 12'h1ad;
    mem[10'b1100100110] = 12'h1ad;
    mem[10'b1100100111] = 12'h1ad;
    mem[10'b1100101000] = 12'h1ae;
    mem[10'b1100101001] = 12'h1ae;
    mem[10'b1100101010] = 12'h1af;
    mem[10'b1100101011] = 12'h1af;
    mem[10'b1100101100] = 12'h1af;
    mem[10'b1100101101] = 12'h1b0;
    mem[10'b1100101110] = 12'h1b0;
    mem[10'b1100101111] = 12'h1b1;
    mem[10'b1100110000] = 12'h1b1;
    mem[10'b1100110001] = 12'h1b1;
    mem[10'b1100110010] = 12'h1b2;
    mem[10'b1100110011] = 12'h1b2;
    mem[10'b1100110100] = 12'h1b3;
    mem[10'b1100110101] = 12'h1b3;
    mem[10'b1100110110] = 12'h1b3;
    mem[10'b1100110111] = 12'h1b4;
    mem[10'b1100111000] = 12'h1b4;
    mem[10'b1100111001] = 12'h1b5;
    mem[10'b1100111010] = 12'h1b5;
    mem[10'b1100111011] = 12'h1b5;
    mem[10'b1100111100] = 12'h1b6;
    mem[10'b1100111101] = 12'h1b6;
    mem[10'b1100111110] = 12'h1b7;
    mem[10'b1100111111] = 12'h1b7;
    mem[10'b1101000000] = 12'h1b7;
    mem[10'b1101000001] = 12'h1b8;
    mem[10'b1101000010] = 12'h1b8;
    mem[10'b1101000011] = 12'h1b9;
    mem[10'b1101000100] = 12'h1b9;
    mem[10'b1101000101] = 12'h1b9;
    mem[10'b1101000110] = 12'h1ba;
    mem[10'b1101000111] = 12'h1ba;
    mem[10'b1101001000] = 12'h1bb;
    mem[10'b1101001001] = 12'h1bb;
    mem[10'b1101001010] = 12'h1bb;
    mem[10'b1101001011] = 12'h1bc;
    mem[10'b1101001100] = 12'h1bc;
    mem[10'b1101001101] = 12'h1bd;
    mem[10'b1101001110] = 12'h1bd;
    mem[10'b1101001111] = 12'h1bd;
    mem[10'b1101010000] = 12'h1be;
    mem[10'b1101010001] = 12'h1be;
    mem[10'b1101010010] = 12'h1bf;
    mem[10'b1101010011] = 12'h1bf;
    mem[10'b1101010100] = 12'h1bf;
    mem[10'b1101010101] = 12'h1c0;
    mem[10'b1101010110] = 12'h1c0;
    mem[10'b1101010111] = 12'h1c1;
    mem[10'b1101011000] = 12'h1c1;
    mem[10'b1101011001] = 12'h1c1;
    mem[10'b1101011010] = 12'h1c2;
    mem[10'b1101011011] = 12'h1c2;
    mem[10'b1101011100] = 12'h1c3;
    mem[10'b1101011101] = 12'h1c3;
    mem[10'b1101011110] = 12'h1c3;
    mem[10'b1101011111] = 12'h1c4;
    mem[10'b1101100000] = 12'h1c4;
    mem[10'b1101100001] = 12'h1c4;
    mem[10'b1101100010] = 12'h1c5;
    mem[10'b1101100011] = 12'h1c5;
    mem[10'b1101100100] = 12'h1c6;
    mem[10'b1101100101] = 12'h1c6;
    mem[10'b1101100110] = 12'h1c6;
    mem[10'b1101100111] = 12'h1c7;
    mem[10'b1101101000] = 12'h1c7;
    mem[10'b1101101001] = 12'h1c8;
    mem[10'b1101101010] = 12'h1c8;
    mem[10'b1101101011] = 12'h1c8;
    mem[10'b1101101100] = 12'h1c9;
    mem[10'b1101101101] = 12'h1c9;
    mem[10'b1101101110] = 12'h1ca;
    mem[10'b1101101111] = 12'h1ca;
    mem[10'b1101110000] = 12'h1ca;
    mem[10'b1101110001] = 12'h1cb;
    mem[10'b1101110010] = 12'h1cb;
    mem[10'b1101110011] = 12'h1cc;
    mem[10'b1101110100] = 12'h1cc;
    mem[10'b1101110101] = 12'h1cc;
    mem[10'b1101110110] = 12'h1cd;
    mem[10'b1101110111] = 12'h1cd;
    mem[10'b1101111000] = 12'h1cd;
    mem[10'b1101111001] = 12'h1ce;
    mem[10'b1101111010] = 12'h1ce;
    mem[10'b1101111011] = 12'h1cf;
    mem[10'b1101111100] = 12'h1cf;
    mem[10'b1101111101] = 12'h1cf;
    mem[10'b1101111110] = 12'h1d0;
    mem[10'b1101111111] = 12'h1d0;
    mem[10'b1110000000] = 12'h1d1;
    mem[10'b1110000001] = 12'h1d1;
    mem[10'b1110000010] = 12'h1d1;
    mem[10'b1110000011] = 12'h1d2;
    mem[10'b1110000100] = 12'h1d2;
    mem[10'b1110000101] = 12'h1d2;
    mem[10'b1110000110] = 12'h1d3;
    mem[10'b1110000111] = 12'h1d3;
    mem[10'b1110001000] = 12'h1d4;
    mem[10'b1110001001] = 12'h1d4;
    mem[10'b1110001010] = 12'h1d4;
    mem[10'b1110001011] = 12'h1d5;
    mem[10'b1110001100] = 12'h1d5;
    mem[10'b1110001101] = 12'h1d6;
    mem[10'b1110001110] = 12'h1d6;
    mem[10'b1110001111] = 12'h1d6;
    mem[10'b1110010000] = 12'h1d7;
    mem[10'b1110010001] = 12'h1d7;
    mem[10'b1110010010] = 12'h1d7;
    mem[10'b1110010011] = 12'h1d8;
    mem[10'b1110010100] = 12'h1d8;
    mem[10'b1110010101] = 12'h1d9;
    mem[10'b1110010110] = 12'h1d9;
    mem[10'b1110010111] = 12'h1d9;
    mem[10'b1110011000] = 12'h1da;
    mem[10'b1110011001] = 12'h1da;
    mem[10'b1110011010] = 12'h1da;
    mem[10'b1110011011] = 12'h1db;
    mem[10'b1110011100] = 12'h1db;
    mem[10'b1110011101] = 12'h1dc;
    mem[10'b1110011110] = 12'h1dc;
    mem[10'b1110011111] = 12'h1dc;
    mem[10'b1110100000] = 12'h1dd;
    mem[10'b1110100001] = 12'h1dd;
    mem[10'b1110100010] = 12'h1dd;
    mem[10'b1110100011] = 12'h1de;
    mem[10'b1110100100] = 12'h1de;
    mem[10'b1110100101] = 12'h1df;
    mem[10'b1110100110] = 12'h1df;
    mem[10'b1110100111] = 12'h1df;
    mem[10'b1110101000] = 12'h1e0;
    mem[10'b1110101001] = 12'h1e0;
    mem[10'b1110101010] = 12'h1e1;
    mem[10'b1110101011] = 12'h1e1;
    mem[10'b1110101100] = 12'h1e1;
    mem[10'b1110101101] = 12'h1e2;
    mem[10'b1110101110] = 12'h1e2;
    mem[10'b1110101111] = 12'h1e2;
    mem[10'b1110110000] = 12'h1e3;
    mem[10'b1110110001] = 12'h1e3;
    mem[10'b1110110010] = 12'h1e4;
    mem[10'b1110110011] = 12'h1e4;
    mem[10'b1110110100] = 12'h1e4;
    mem[10'b1110110101] = 12'h1e5;
    mem[10'b1110110110] = 12'h1e5;
    mem[10'b1110110111] = 12'h1e5;
    mem[10'b1110111000] = 12'h1e6;
    mem[10'b1110111001] = 12'h1e6;
    mem[10'b1110111010] = 12'h1e6;
    mem[10'b1110111011] = 12'h1e7;
    mem[10'b1110111100] = 12'h1e7;
    mem[10'b1110111101] = 12'h1e8;
    mem[10'b1110111110] = 12'h1e8;
    mem[10'b1110111111] = 12'h1e8;
    mem[10'b1111000000] = 12'h1e9;
    mem[10'b1111000001] = 12'h1e9;
    mem[10'b1111000010] = 12'h1e9;
    mem[10'b1111000011] = 12'h1ea;
    mem[10'b1111000100] = 12'h1ea;
    mem[10'b1111000101] = 12'h1eb;
    mem[10'b1111000110] = 12'h1eb;
    mem[10'b1111000111] = 12'h1eb;
    mem[10'b1111001000] = 12'h1ec;
    mem[10'b1111001001] = 12'h1ec;
    mem[10'b1111001010] = 12'h1ec;
    mem[10'b1111001011] = 12'h1ed;
    mem[10'b1111001100] = 12'h1ed;
    mem[10'b1111001101] = 12'h1ee;
    mem[10'b1111001110] = 12'h1ee;
    mem[10'b1111001111] = 12'h1ee;
    mem[10'b1111010000] = 12'h1ef;
    mem[10'b1111010001] = 12'h1ef;
    mem[10'b1111010010] = 12'h1ef;
    mem[10'b1111010011] = 12'h1f0;
    mem[10'b1111010100] = 12'h1f0;
    mem[10'b1111010101] = 12'h1f1;
    mem[10'b1111010110] = 12'h1f1;
    mem[10'b1111010111] = 12'h1f1;
    mem[10'b1111011000] = 12'h1f2;
    mem[10'b1111011001] = 12'h1f2;
    mem[10'b1111011010] = 12'h1f2;
    mem[10'b1111011011] = 12'h1f3;
    mem[10'b1111011100] = 12'h1f3;
    mem[10'b1111011101] = 12'h1f3;
    mem[10'b1111011110] = 12'h1f4;
    mem[10'b1111011111] = 12'h1f4;
    mem[10'b1111100000] = 12'h1f5;
    mem[10'b1111100001] = 12'h1f5;
    mem[10'b1111100010] = 12'h1f5;
    mem[10'b1111100011] = 12'h1f6;
    mem[10'b1111100100] = 12'h1f6;
    mem[10'b1111100101] = 12'h1f6;
    mem[10'b1111100110] = 12'h1f7;
    mem[10'b1111100111] = 12'h1f7;
    mem[10'b1111101000] = 12'h1f7;
    mem[10'b1111101001] = 12'h1f8;
    mem[10'b1111101010] = 12'h1f8;
    mem[10'b1111101011] = 12'h1f9;
    mem[10'b1111101100] = 12'h1f9;
    mem[10'b1111101101] = 12'h1f9;
    mem[10'b1111101110] = 12'h1fa;
    mem[10'b1111101111] = 12'h1fa;
    mem[10'b1111110000] = 12'h1fa;
    mem[10'b1111110001] = 12'h1fb;
    mem[10'b1111110010] = 12'h1fb;
    mem[10'b1111110011] = 12'h1fb;
    mem[10'b1111110100] = 12'h1fc;
    mem[10'b1111110101] = 12'h1fc;
    mem[10'b1111110110] = 12'h1fd;
    mem[10'b1111110111] = 12'h1fd;
    mem[10'b1111111000] = 12'h1fd;
    mem[10'b1111111001] = 12'h1fe;
    mem[10'b1111111010] = 12'h1fe;
    mem[10'b1111111011] = 12'h1fe;
    mem[10'b1111111100] = 12'h1ff;
    mem[10'b1111111101] = 12'h1ff;
    mem[10'b1111111110] = 12'h1ff;
    mem[10'b1111111111] = 12'h200;
    end
    
    always @(posedge clock) begin
       data <= mem[address];
    end
endmodule // texture_path$unit$coords$log_r


module texture_path$unit$coords$mul_g$0(a,b,p);
    
    // Module arguments
    input wire  [28:0] a;
    input wire  [29:0] b;
    output reg  [58:0] p;
    
    // Update code (custom)
    // p = low 59 bits of a * b, both signed: a signed 59-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_path$unit$coords$mul_g$0


module texture_path$unit$coords$mul_g$1(a,b,p);
    
    // Module arguments
    input wire  [28:0] a;
    input wire  [29:0] b;
    output reg  [58:0] p;
    
    // Update code (custom)
    // p = low 59 bits of a * b, both signed: a signed 59-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_path$unit$coords$mul_g$1


module texture_path$unit$coords$mul_g$2(a,b,p);
    
    // Module arguments
    input wire  [28:0] a;
    input wire  [29:0] b;
    output reg  [58:0] p;
    
    // Update code (custom)
    // p = low 59 bits of a * b, both signed: a signed 59-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_path$unit$coords$mul_g$2


module texture_path$unit$coords$mul_g$3(a,b,p);
    
    // Module arguments
    input wire  [28:0] a;
    input wire  [29:0] b;
    output reg  [58:0] p;
    
    // Update code (custom)
    // p = low 59 bits of a * b, both signed: a signed 59-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_path$unit$coords$mul_g$3


module texture_path$unit$coords$mul_s(a,b,p);
    
    // Module arguments
    input wire  [28:0] a;
    input wire  [26:0] b;
    output reg  [55:0] p;
    
    // Update code (custom)
    // p = low 56 bits of a * b, both signed: a signed 56-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_path$unit$coords$mul_s


module texture_path$unit$coords$mul_sq$0(a,b,p);
    
    // Module arguments
    input wire  [47:0] a;
    input wire  [47:0] b;
    output reg  [95:0] p;
    
    // Update code (custom)
    // p = low 96 bits of a * b, both signed: a signed 96-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_path$unit$coords$mul_sq$0


module texture_path$unit$coords$mul_sq$1(a,b,p);
    
    // Module arguments
    input wire  [47:0] a;
    input wire  [47:0] b;
    output reg  [95:0] p;
    
    // Update code (custom)
    // p = low 96 bits of a * b, both signed: a signed 96-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_path$unit$coords$mul_sq$1


module texture_path$unit$coords$mul_sq$2(a,b,p);
    
    // Module arguments
    input wire  [47:0] a;
    input wire  [47:0] b;
    output reg  [95:0] p;
    
    // Update code (custom)
    // p = low 96 bits of a * b, both signed: a signed 96-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_path$unit$coords$mul_sq$2


module texture_path$unit$coords$mul_sq$3(a,b,p);
    
    // Module arguments
    input wire  [47:0] a;
    input wire  [47:0] b;
    output reg  [95:0] p;
    
    // Update code (custom)
    // p = low 96 bits of a * b, both signed: a signed 96-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_path$unit$coords$mul_sq$3


module texture_path$unit$coords$mul_t(a,b,p);
    
    // Module arguments
    input wire  [28:0] a;
    input wire  [26:0] b;
    output reg  [55:0] p;
    
    // Update code (custom)
    // p = low 56 bits of a * b, both signed: a signed 56-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_path$unit$coords$mul_t


module texture_path$unit$coords$num$0(dxq,p,size_log2,u);
    
    // Module arguments
    input wire  [32:0] dxq;
    input wire  [34:0] p;
    input wire  [3:0] size_log2;
    output reg  [46:0] u;
    
    // Constant declarations
    localparam  dst_msb = 8'h20;
    localparam  pgs_msb = 8'h22;
    localparam  g_msb = 8'h23;
    localparam  ext_dst = 36'he00000000;
    localparam  ext_pgs = 36'h800000000;
    
    // Local signals
    reg  [35:0] g;
    reg  [34:0] g_abs;
    
    // Update code
    always @(*) begin
        g = ((dxq) & 36'hfffffffff) - ((p) & 36'hfffffffff);
        if (dxq[dst_msb]) begin
            g = g + ext_dst;
        end
        if (p[pgs_msb]) begin
            g = g - ext_pgs;
        end
        g_abs = g[(32'h0)+:(35)];
        if (g[g_msb]) begin
            g_abs = ~g_abs + 32'h1;
        end
        u = ((g_abs) & 47'h7fffffffffff) << ((size_log2) & 47'h7fffffffffff);
    end
    
endmodule // texture_path$unit$coords$num$0


module texture_path$unit$coords$num$1(dxq,p,size_log2,u);
    
    // Module arguments
    input wire  [32:0] dxq;
    input wire  [34:0] p;
    input wire  [3:0] size_log2;
    output reg  [46:0] u;
    
    // Constant declarations
    localparam  dst_msb = 8'h20;
    localparam  pgs_msb = 8'h22;
    localparam  g_msb = 8'h23;
    localparam  ext_dst = 36'he00000000;
    localparam  ext_pgs = 36'h800000000;
    
    // Local signals
    reg  [35:0] g;
    reg  [34:0] g_abs;
    
    // Update code
    always @(*) begin
        g = ((dxq) & 36'hfffffffff) - ((p) & 36'hfffffffff);
        if (dxq[dst_msb]) begin
            g = g + ext_dst;
        end
        if (p[pgs_msb]) begin
            g = g - ext_pgs;
        end
        g_abs = g[(32'h0)+:(35)];
        if (g[g_msb]) begin
            g_abs = ~g_abs + 32'h1;
        end
        u = ((g_abs) & 47'h7fffffffffff) << ((size_log2) & 47'h7fffffffffff);
    end
    
endmodule // texture_path$unit$coords$num$1


module texture_path$unit$coords$num$2(dxq,p,size_log2,u);
    
    // Module arguments
    input wire  [32:0] dxq;
    input wire  [34:0] p;
    input wire  [3:0] size_log2;
    output reg  [46:0] u;
    
    // Constant declarations
    localparam  dst_msb = 8'h20;
    localparam  pgs_msb = 8'h22;
    localparam  g_msb = 8'h23;
    localparam  ext_dst = 36'he00000000;
    localparam  ext_pgs = 36'h800000000;
    
    // Local signals
    reg  [35:0] g;
    reg  [34:0] g_abs;
    
    // Update code
    always @(*) begin
        g = ((dxq) & 36'hfffffffff) - ((p) & 36'hfffffffff);
        if (dxq[dst_msb]) begin
            g = g + ext_dst;
        end
        if (p[pgs_msb]) begin
            g = g - ext_pgs;
        end
        g_abs = g[(32'h0)+:(35)];
        if (g[g_msb]) begin
            g_abs = ~g_abs + 32'h1;
        end
        u = ((g_abs) & 47'h7fffffffffff) << ((size_log2) & 47'h7fffffffffff);
    end
    
endmodule // texture_path$unit$coords$num$2


module texture_path$unit$coords$num$3(dxq,p,size_log2,u);
    
    // Module arguments
    input wire  [32:0] dxq;
    input wire  [34:0] p;
    input wire  [3:0] size_log2;
    output reg  [46:0] u;
    
    // Constant declarations
    localparam  dst_msb = 8'h20;
    localparam  pgs_msb = 8'h22;
    localparam  g_msb = 8'h23;
    localparam  ext_dst = 36'he00000000;
    localparam  ext_pgs = 36'h800000000;
    
    // Local signals
    reg  [35:0] g;
    reg  [34:0] g_abs;
    
    // Update code
    always @(*) begin
        g = ((dxq) & 36'hfffffffff) - ((p) & 36'hfffffffff);
        if (dxq[dst_msb]) begin
            g = g + ext_dst;
        end
        if (p[pgs_msb]) begin
            g = g - ext_pgs;
        end
        g_abs = g[(32'h0)+:(35)];
        if (g[g_msb]) begin
            g_abs = ~g_abs + 32'h1;
        end
        u = ((g_abs) & 47'h7fffffffffff) << ((size_log2) & 47'h7fffffffffff);
    end
    
endmodule // texture_path$unit$coords$num$3


module texture_path$unit$coords$recip(clock,inp_valid,inp_ready,hold,inp_n,inp_d,out_valid,out_ready,out_q,out_r);
    
    // Module arguments
    input wire  clock;
    input wire  inp_valid;
    output reg  inp_ready;
    input wire  hold;
    input wire  [46:0] inp_n;
    input wire  [20:0] inp_d;
    output reg  out_valid;
    input wire  out_ready;
    output reg  [26:0] out_q;
    output reg  [20:0] out_r;
    
    // Constant declarations
    localparam  n_msb = 8'h2e;
    localparam  qm = 8'h1a;
    localparam  q_sign = 27'h4000000;
    
    // Stub signals
    reg  stages$0$clock;
    reg  stages$0$enable;
    reg  stages$0$valid_in;
    reg  [20:0] stages$0$p_in;
    reg  [25:0] stages$0$x_in;
    reg  [20:0] stages$0$d_in;
    reg  stages$0$neg_in;
    wire  stages$0$valid;
    wire  [20:0] stages$0$p;
    wire  [25:0] stages$0$x;
    wire  [20:0] stages$0$d;
    wire  stages$0$neg;
    reg  stages$1$clock;
    reg  stages$1$enable;
    reg  stages$1$valid_in;
    reg  [20:0] stages$1$p_in;
    reg  [25:0] stages$1$x_in;
    reg  [20:0] stages$1$d_in;
    reg  stages$1$neg_in;
    wire  stages$1$valid;
    wire  [20:0] stages$1$p;
    wire  [25:0] stages$1$x;
    wire  [20:0] stages$1$d;
    wire  stages$1$neg;
    reg  stages$2$clock;
    reg  stages$2$enable;
    reg  stages$2$valid_in;
    reg  [20:0] stages$2$p_in;
    reg  [25:0] stages$2$x_in;
    reg  [20:0] stages$2$d_in;
    reg  stages$2$neg_in;
    wire  stages$2$valid;
    wire  [20:0] stages$2$p;
    wire  [25:0] stages$2$x;
    wire  [20:0] stages$2$d;
    wire  stages$2$neg;
    reg  stages$3$clock;
    reg  stages$3$enable;
    reg  stages$3$valid_in;
    reg  [20:0] stages$3$p_in;
    reg  [25:0] stages$3$x_in;
    reg  [20:0] stages$3$d_in;
    reg  stages$3$neg_in;
    wire  stages$3$valid;
    wire  [20:0] stages$3$p;
    wire  [25:0] stages$3$x;
    wire  [20:0] stages$3$d;
    wire  stages$3$neg;
    reg  stages$4$clock;
    reg  stages$4$enable;
    reg  stages$4$valid_in;
    reg  [20:0] stages$4$p_in;
    reg  [25:0] stages$4$x_in;
    reg  [20:0] stages$4$d_in;
    reg  stages$4$neg_in;
    wire  stages$4$valid;
    wire  [20:0] stages$4$p;
    wire  [25:0] stages$4$x;
    wire  [20:0] stages$4$d;
    wire  stages$4$neg;
    reg  stages$5$clock;
    reg  stages$5$enable;
    reg  stages$5$valid_in;
    reg  [20:0] stages$5$p_in;
    reg  [25:0] stages$5$x_in;
    reg  [20:0] stages$5$d_in;
    reg  stages$5$neg_in;
    wire  stages$5$valid;
    wire  [20:0] stages$5$p;
    wire  [25:0] stages$5$x;
    wire  [20:0] stages$5$d;
    wire  stages$5$neg;
    reg  stages$6$clock;
    reg  stages$6$enable;
    reg  stages$6$valid_in;
    reg  [20:0] stages$6$p_in;
    reg  [25:0] stages$6$x_in;
    reg  [20:0] stages$6$d_in;
    reg  stages$6$neg_in;
    wire  stages$6$valid;
    wire  [20:0] stages$6$p;
    wire  [25:0] stages$6$x;
    wire  [20:0] stages$6$d;
    wire  stages$6$neg;
    reg  stages$7$clock;
    reg  stages$7$enable;
    reg  stages$7$valid_in;
    reg  [20:0] stages$7$p_in;
    reg  [25:0] stages$7$x_in;
    reg  [20:0] stages$7$d_in;
    reg  stages$7$neg_in;
    wire  stages$7$valid;
    wire  [20:0] stages$7$p;
    wire  [25:0] stages$7$x;
    wire  [20:0] stages$7$d;
    wire  stages$7$neg;
    reg  stages$8$clock;
    reg  stages$8$enable;
    reg  stages$8$valid_in;
    reg  [20:0] stages$8$p_in;
    reg  [25:0] stages$8$x_in;
    reg  [20:0] stages$8$d_in;
    reg  stages$8$neg_in;
    wire  stages$8$valid;
    wire  [20:0] stages$8$p;
    wire  [25:0] stages$8$x;
    wire  [20:0] stages$8$d;
    wire  stages$8$neg;
    reg  stages$9$clock;
    reg  stages$9$enable;
    reg  stages$9$valid_in;
    reg  [20:0] stages$9$p_in;
    reg  [25:0] stages$9$x_in;
    reg  [20:0] stages$9$d_in;
    reg  stages$9$neg_in;
    wire  stages$9$valid;
    wire  [20:0] stages$9$p;
    wire  [25:0] stages$9$x;
    wire  [20:0] stages$9$d;
    wire  stages$9$neg;
    reg  stages$10$clock;
    reg  stages$10$enable;
    reg  stages$10$valid_in;
    reg  [20:0] stages$10$p_in;
    reg  [25:0] stages$10$x_in;
    reg  [20:0] stages$10$d_in;
    reg  stages$10$neg_in;
    wire  stages$10$valid;
    wire  [20:0] stages$10$p;
    wire  [25:0] stages$10$x;
    wire  [20:0] stages$10$d;
    wire  stages$10$neg;
    reg  stages$11$clock;
    reg  stages$11$enable;
    reg  stages$11$valid_in;
    reg  [20:0] stages$11$p_in;
    reg  [25:0] stages$11$x_in;
    reg  [20:0] stages$11$d_in;
    reg  stages$11$neg_in;
    wire  stages$11$valid;
    wire  [20:0] stages$11$p;
    wire  [25:0] stages$11$x;
    wire  [20:0] stages$11$d;
    wire  stages$11$neg;
    reg  stages$12$clock;
    reg  stages$12$enable;
    reg  stages$12$valid_in;
    reg  [20:0] stages$12$p_in;
    reg  [25:0] stages$12$x_in;
    reg  [20:0] stages$12$d_in;
    reg  stages$12$neg_in;
    wire  stages$12$valid;
    wire  [20:0] stages$12$p;
    wire  [25:0] stages$12$x;
    wire  [20:0] stages$12$d;
    wire  stages$12$neg;
    
    // Local signals
    reg  advance;
    reg  [46:0] m;
    reg  [25:0] last_x;
    
    // Sub module instances
    texture_path$unit$coords$recip$stages$0 stages$0(
        .clock(stages$0$clock),
        .enable(stages$0$enable),
        .valid_in(stages$0$valid_in),
        .p_in(stages$0$p_in),
        .x_in(stages$0$x_in),
        .d_in(stages$0$d_in),
        .neg_in(stages$0$neg_in),
        .valid(stages$0$valid),
        .p(stages$0$p),
        .x(stages$0$x),
        .d(stages$0$d),
        .neg(stages$0$neg)
    );
    texture_path$unit$coords$recip$stages$1 stages$1(
        .clock(stages$1$clock),
        .enable(stages$1$enable),
        .valid_in(stages$1$valid_in),
        .p_in(stages$1$p_in),
        .x_in(stages$1$x_in),
        .d_in(stages$1$d_in),
        .neg_in(stages$1$neg_in),
        .valid(stages$1$valid),
        .p(stages$1$p),
        .x(stages$1$x),
        .d(stages$1$d),
        .neg(stages$1$neg)
    );
    texture_path$unit$coords$recip$stages$2 stages$2(
        .clock(stages$2$clock),
        .enable(stages$2$enable),
        .valid_in(stages$2$valid_in),
        .p_in(stages$2$p_in),
        .x_in(stages$2$x_in),
        .d_in(stages$2$d_in),
        .neg_in(stages$2$neg_in),
        .valid(stages$2$valid),
        .p(stages$2$p),
        .x(stages$2$x),
        .d(stages$2$d),
        .neg(stages$2$neg)
    );
    texture_path$unit$coords$recip$stages$3 stages$3(
        .clock(stages$3$clock),
        .enable(stages$3$enable),
        .valid_in(stages$3$valid_in),
        .p_in(stages$3$p_in),
        .x_in(stages$3$x_in),
        .d_in(stages$3$d_in),
        .neg_in(stages$3$neg_in),
        .valid(stages$3$valid),
        .p(stages$3$p),
        .x(stages$3$x),
        .d(stages$3$d),
        .neg(stages$3$neg)
    );
    texture_path$unit$coords$recip$stages$4 stages$4(
        .clock(stages$4$clock),
        .enable(stages$4$enable),
        .valid_in(stages$4$valid_in),
        .p_in(stages$4$p_in),
        .x_in(stages$4$x_in),
        .d_in(stages$4$d_in),
        .neg_in(stages$4$neg_in),
        .valid(stages$4$valid),
        .p(stages$4$p),
        .x(stages$4$x),
        .d(stages$4$d),
        .neg(stages$4$neg)
    );
    texture_path$unit$coords$recip$stages$5 stages$5(
        .clock(stages$5$clock),
        .enable(stages$5$enable),
        .valid_in(stages$5$valid_in),
        .p_in(stages$5$p_in),
        .x_in(stages$5$x_in),
        .d_in(stages$5$d_in),
        .neg_in(stages$5$neg_in),
        .valid(stages$5$valid),
        .p(stages$5$p),
        .x(stages$5$x),
        .d(stages$5$d),
        .neg(stages$5$neg)
    );
    texture_path$unit$coords$recip$stages$6 stages$6(
        .clock(stages$6$clock),
        .enable(stages$6$enable),
        .valid_in(stages$6$valid_in),
        .p_in(stages$6$p_in),
        .x_in(stages$6$x_in),
        .d_in(stages$6$d_in),
        .neg_in(stages$6$neg_in),
        .valid(stages$6$valid),
        .p(stages$6$p),
        .x(stages$6$x),
        .d(stages$6$d),
        .neg(stages$6$neg)
    );
    texture_path$unit$coords$recip$stages$7 stages$7(
        .clock(stages$7$clock),
        .enable(stages$7$enable),
        .valid_in(stages$7$valid_in),
        .p_in(stages$7$p_in),
        .x_in(stages$7$x_in),
        .d_in(stages$7$d_in),
        .neg_in(stages$7$neg_in),
        .valid(stages$7$valid),
        .p(stages$7$p),
        .x(stages$7$x),
        .d(stages$7$d),
        .neg(stages$7$neg)
    );
    texture_path$unit$coords$recip$stages$8 stages$8(
        .clock(stages$8$clock),
        .enable(stages$8$enable),
        .valid_in(stages$8$valid_in),
        .p_in(stages$8$p_in),
        .x_in(stages$8$x_in),
        .d_in(stages$8$d_in),
        .neg_in(stages$8$neg_in),
        .valid(stages$8$valid),
        .p(stages$8$p),
        .x(stages$8$x),
        .d(stages$8$d),
        .neg(stages$8$neg)
    );
    texture_path$unit$coords$recip$stages$9 stages$9(
        .clock(stages$9$clock),
        .enable(stages$9$enable),
        .valid_in(stages$9$valid_in),
        .p_in(stages$9$p_in),
        .x_in(stages$9$x_in),
        .d_in(stages$9$d_in),
        .neg_in(stages$9$neg_in),
        .valid(stages$9$valid),
        .p(stages$9$p),
        .x(stages$9$x),
        .d(stages$9$d),
        .neg(stages$9$neg)
    );
    texture_path$unit$coords$recip$stages$10 stages$10(
        .clock(stages$10$clock),
        .enable(stages$10$enable),
        .valid_in(stages$10$valid_in),
        .p_in(stages$10$p_in),
        .x_in(stages$10$x_in),
        .d_in(stages$10$d_in),
        .neg_in(stages$10$neg_in),
        .valid(stages$10$valid),
        .p(stages$10$p),
        .x(stages$10$x),
        .d(stages$10$d),
        .neg(stages$10$neg)
    );
    texture_path$unit$coords$recip$stages$11 stages$11(
        .clock(stages$11$clock),
        .enable(stages$11$enable),
        .valid_in(stages$11$valid_in),
        .p_in(stages$11$p_in),
        .x_in(stages$11$x_in),
        .d_in(stages$11$d_in),
        .neg_in(stages$11$neg_in),
        .valid(stages$11$valid),
        .p(stages$11$p),
        .x(stages$11$x),
        .d(stages$11$d),
        .neg(stages$11$neg)
    );
    texture_path$unit$coords$recip$stages$12 stages$12(
        .clock(stages$12$clock),
        .enable(stages$12$enable),
        .valid_in(stages$12$valid_in),
        .p_in(stages$12$p_in),
        .x_in(stages$12$x_in),
        .d_in(stages$12$d_in),
        .neg_in(stages$12$neg_in),
        .valid(stages$12$valid),
        .p(stages$12$p),
        .x(stages$12$x),
        .d(stages$12$d),
        .neg(stages$12$neg)
    );
    
    // Update code
    always @(*) begin
        advance = ~hold & (~stages$12$valid | out_ready);
        out_valid = stages$12$valid;
        last_x = stages$12$x;
        out_r = stages$12$p;
        out_q = ((last_x) & 27'h7ffffff);
        if (stages$12$neg) begin
            out_q = ((last_x) & 27'h7ffffff) | q_sign;
        end
        stages$0$clock = clock;
        stages$0$enable = advance;
        stages$1$clock = clock;
        stages$1$enable = advance;
        stages$2$clock = clock;
        stages$2$enable = advance;
        stages$3$clock = clock;
        stages$3$enable = advance;
        stages$4$clock = clock;
        stages$4$enable = advance;
        stages$5$clock = clock;
        stages$5$enable = advance;
        stages$6$clock = clock;
        stages$6$enable = advance;
        stages$7$clock = clock;
        stages$7$enable = advance;
        stages$8$clock = clock;
        stages$8$enable = advance;
        stages$9$clock = clock;
        stages$9$enable = advance;
        stages$10$clock = clock;
        stages$10$enable = advance;
        stages$11$clock = clock;
        stages$11$enable = advance;
        stages$12$clock = clock;
        stages$12$enable = advance;
        inp_ready = advance;
        m = inp_n;
        if (inp_n[n_msb]) begin
            m = ~inp_n;
        end
        stages$0$valid_in = inp_valid;
        stages$0$p_in = ((m >> qm) & 21'h1fffff);
        stages$0$x_in = m[(32'h0)+:(26)];
        stages$0$d_in = inp_d;
        stages$0$neg_in = inp_n[n_msb];
        stages$1$valid_in = stages$0$valid;
        stages$1$p_in = stages$0$p;
        stages$1$x_in = stages$0$x;
        stages$1$d_in = stages$0$d;
        stages$1$neg_in = stages$0$neg;
        stages$2$valid_in = stages$1$valid;
        stages$2$p_in = stages$1$p;
        stages$2$x_in = stages$1$x;
        stages$2$d_in = stages$1$d;
        stages$2$neg_in = stages$1$neg;
        stages$3$valid_in = stages$2$valid;
        stages$3$p_in = stages$2$p;
        stages$3$x_in = stages$2$x;
        stages$3$d_in = stages$2$d;
        stages$3$neg_in = stages$2$neg;
        stages$4$valid_in = stages$3$valid;
        stages$4$p_in = stages$3$p;
        stages$4$x_in = stages$3$x;
        stages$4$d_in = stages$3$d;
        stages$4$neg_in = stages$3$neg;
        stages$5$valid_in = stages$4$valid;
        stages$5$p_in = stages$4$p;
        stages$5$x_in = stages$4$x;
        stages$5$d_in = stages$4$d;
        stages$5$neg_in = stages$4$neg;
        stages$6$valid_in = stages$5$valid;
        stages$6$p_in = stages$5$p;
        stages$6$x_in = stages$5$x;
        stages$6$d_in = stages$5$d;
        stages$6$neg_in = stages$5$neg;
        stages$7$valid_in = stages$6$valid;
        stages$7$p_in = stages$6$p;
        stages$7$x_in = stages$6$x;
        stages$7$d_in = stages$6$d;
        stages$7$neg_in = stages$6$neg;
        stages$8$valid_in = stages$7$valid;
        stages$8$p_in = stages$7$p;
        stages$8$x_in = stages$7$x;
        stages$8$d_in = stages$7$d;
        stages$8$neg_in = stages$7$neg;
        stages$9$valid_in = stages$8$valid;
        stages$9$p_in = stages$8$p;
        stages$9$x_in = stages$8$x;
        stages$9$d_in = stages$8$d;
        stages$9$neg_in = stages$8$neg;
        stages$10$valid_in = stages$9$valid;
        stages$10$p_in = stages$9$p;
        stages$10$x_in = stages$9$x;
        stages$10$d_in = stages$9$d;
        stages$10$neg_in = stages$9$neg;
        stages$11$valid_in = stages$10$valid;
        stages$11$p_in = stages$10$p;
        stages$11$x_in = stages$10$x;
        stages$11$d_in = stages$10$d;
        stages$11$neg_in = stages$10$neg;
        stages$12$valid_in = stages$11$valid;
        stages$12$p_in = stages$11$p;
        stages$12$x_in = stages$11$x;
        stages$12$d_in = stages$11$d;
        stages$12$neg_in = stages$11$neg;
    end
    
endmodule // texture_path$unit$coords$recip


module texture_path$unit$coords$recip$stages$0(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [20:0] p_in;
    input wire  [25:0] x_in;
    input wire  [20:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [20:0] p;
    output reg  [25:0] x;
    output reg  [20:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h15;
    localparam  x_msb = 8'h19;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [20:0] p_r$d;
    wire  [20:0] p_r$q;
    reg  p_r$clock;
    reg  [25:0] x_r$d;
    wire  [25:0] x_r$q;
    reg  x_r$clock;
    reg  [20:0] d_r$d;
    wire  [20:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [21:0] tp$0;
    reg  [21:0] tp$1;
    reg  [21:0] tp$2;
    reg  [25:0] tx$0;
    reg  [25:0] tx$1;
    reg  [25:0] tx$2;
    reg  [21:0] t$0;
    reg  [21:0] t$1;
    reg  [21:0] diff$0;
    reg  [21:0] diff$1;
    reg  [21:0] d1;
    
    // Sub module instances
    texture_path$unit$coords$recip$stages$0$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    texture_path$unit$coords$recip$stages$0$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    texture_path$unit$coords$recip$stages$0$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    texture_path$unit$coords$recip$stages$0$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    texture_path$unit$coords$recip$stages$0$neg_r neg_r(
        .d(neg_r$d),
        .q(neg_r$q),
        .clock(neg_r$clock)
    );
    
    // Update code
    always @(*) begin
        valid_r$clock = clock;
        p_r$clock = clock;
        x_r$clock = clock;
        d_r$clock = clock;
        neg_r$clock = clock;
        valid_r$d = valid_r$q;
        p_r$d = p_r$q;
        x_r$d = x_r$q;
        d_r$d = d_r$q;
        neg_r$d = neg_r$q;
        d1 = ((d_in) & 22'h3fffff);
        tp$0 = ((p_in) & 22'h3fffff);
        tx$0 = x_in;
        t$0 = tp$0 << 32'h1;
        if (tx$0[x_msb]) begin
            t$0 = (tp$0 << 32'h1) | 32'h1;
        end
        diff$0 = t$0 - d1;
        if (diff$0[borrow]) begin
            tp$1 = t$0;
            tx$1 = tx$0 << 32'h1;
        end
        else begin
            tp$1 = diff$0;
            tx$1 = (tx$0 << 32'h1) | 32'h1;
        end
        t$1 = tp$1 << 32'h1;
        if (tx$1[x_msb]) begin
            t$1 = (tp$1 << 32'h1) | 32'h1;
        end
        diff$1 = t$1 - d1;
        if (diff$1[borrow]) begin
            tp$2 = t$1;
            tx$2 = tx$1 << 32'h1;
        end
        else begin
            tp$2 = diff$1;
            tx$2 = (tx$1 << 32'h1) | 32'h1;
        end
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$2[(32'h0)+:(21)];
            x_r$d = tx$2;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$2[(32'h0)+:(21)] - 32'h1;
                x_r$d = ~tx$2;
            end
            d_r$d = d_in;
            neg_r$d = neg_in;
        end
        valid = valid_r$q;
        p = p_r$q;
        x = x_r$q;
        d = d_r$q;
        neg = neg_r$q;
    end
    
endmodule // texture_path$unit$coords$recip$stages$0


module texture_path$unit$coords$recip$stages$0$d_r(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$0$d_r


module texture_path$unit$coords$recip$stages$0$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$0$neg_r


module texture_path$unit$coords$recip$stages$0$p_r(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$0$p_r


module texture_path$unit$coords$recip$stages$0$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$0$valid_r


module texture_path$unit$coords$recip$stages$0$x_r(d,q,clock);
    
    // Module arguments
    input wire  [25:0] d;
    output reg  [25:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 26'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$0$x_r


module texture_path$unit$coords$recip$stages$1(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [20:0] p_in;
    input wire  [25:0] x_in;
    input wire  [20:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [20:0] p;
    output reg  [25:0] x;
    output reg  [20:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h15;
    localparam  x_msb = 8'h19;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [20:0] p_r$d;
    wire  [20:0] p_r$q;
    reg  p_r$clock;
    reg  [25:0] x_r$d;
    wire  [25:0] x_r$q;
    reg  x_r$clock;
    reg  [20:0] d_r$d;
    wire  [20:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [21:0] tp$0;
    reg  [21:0] tp$1;
    reg  [21:0] tp$2;
    reg  [25:0] tx$0;
    reg  [25:0] tx$1;
    reg  [25:0] tx$2;
    reg  [21:0] t$0;
    reg  [21:0] t$1;
    reg  [21:0] diff$0;
    reg  [21:0] diff$1;
    reg  [21:0] d1;
    
    // Sub module instances
    texture_path$unit$coords$recip$stages$1$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    texture_path$unit$coords$recip$stages$1$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    texture_path$unit$coords$recip$stages$1$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    texture_path$unit$coords$recip$stages$1$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    texture_path$unit$coords$recip$stages$1$neg_r neg_r(
        .d(neg_r$d),
        .q(neg_r$q),
        .clock(neg_r$clock)
    );
    
    // Update code
    always @(*) begin
        valid_r$clock = clock;
        p_r$clock = clock;
        x_r$clock = clock;
        d_r$clock = clock;
        neg_r$clock = clock;
        valid_r$d = valid_r$q;
        p_r$d = p_r$q;
        x_r$d = x_r$q;
        d_r$d = d_r$q;
        neg_r$d = neg_r$q;
        d1 = ((d_in) & 22'h3fffff);
        tp$0 = ((p_in) & 22'h3fffff);
        tx$0 = x_in;
        t$0 = tp$0 << 32'h1;
        if (tx$0[x_msb]) begin
            t$0 = (tp$0 << 32'h1) | 32'h1;
        end
        diff$0 = t$0 - d1;
        if (diff$0[borrow]) begin
            tp$1 = t$0;
            tx$1 = tx$0 << 32'h1;
        end
        else begin
            tp$1 = diff$0;
            tx$1 = (tx$0 << 32'h1) | 32'h1;
        end
        t$1 = tp$1 << 32'h1;
        if (tx$1[x_msb]) begin
            t$1 = (tp$1 << 32'h1) | 32'h1;
        end
        diff$1 = t$1 - d1;
        if (diff$1[borrow]) begin
            tp$2 = t$1;
            tx$2 = tx$1 << 32'h1;
        end
        else begin
            tp$2 = diff$1;
            tx$2 = (tx$1 << 32'h1) | 32'h1;
        end
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$2[(32'h0)+:(21)];
            x_r$d = tx$2;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$2[(32'h0)+:(21)] - 32'h1;
                x_r$d = ~tx$2;
            end
            d_r$d = d_in;
            neg_r$d = neg_in;
        end
        valid = valid_r$q;
        p = p_r$q;
        x = x_r$q;
        d = d_r$q;
        neg = neg_r$q;
    end
    
endmodule // texture_path$unit$coords$recip$stages$1


module texture_path$unit$coords$recip$stages$1$d_r(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$1$d_r


module texture_path$unit$coords$recip$stages$1$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$1$neg_r


module texture_path$unit$coords$recip$stages$1$p_r(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$1$p_r


module texture_path$unit$coords$recip$stages$1$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$1$valid_r


module texture_path$unit$coords$recip$stages$1$x_r(d,q,clock);
    
    // Module arguments
    input wire  [25:0] d;
    output reg  [25:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 26'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$1$x_r


module texture_path$unit$coords$recip$stages$10(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [20:0] p_in;
    input wire  [25:0] x_in;
    input wire  [20:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [20:0] p;
    output reg  [25:0] x;
    output reg  [20:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h15;
    localparam  x_msb = 8'h19;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [20:0] p_r$d;
    wire  [20:0] p_r$q;
    reg  p_r$clock;
    reg  [25:0] x_r$d;
    wire  [25:0] x_r$q;
    reg  x_r$clock;
    reg  [20:0] d_r$d;
    wire  [20:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [21:0] tp$0;
    reg  [21:0] tp$1;
    reg  [21:0] tp$2;
    reg  [25:0] tx$0;
    reg  [25:0] tx$1;
    reg  [25:0] tx$2;
    reg  [21:0] t$0;
    reg  [21:0] t$1;
    reg  [21:0] diff$0;
    reg  [21:0] diff$1;
    reg  [21:0] d1;
    
    // Sub module instances
    texture_path$unit$coords$recip$stages$10$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    texture_path$unit$coords$recip$stages$10$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    texture_path$unit$coords$recip$stages$10$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    texture_path$unit$coords$recip$stages$10$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    texture_path$unit$coords$recip$stages$10$neg_r neg_r(
        .d(neg_r$d),
        .q(neg_r$q),
        .clock(neg_r$clock)
    );
    
    // Update code
    always @(*) begin
        valid_r$clock = clock;
        p_r$clock = clock;
        x_r$clock = clock;
        d_r$clock = clock;
        neg_r$clock = clock;
        valid_r$d = valid_r$q;
        p_r$d = p_r$q;
        x_r$d = x_r$q;
        d_r$d = d_r$q;
        neg_r$d = neg_r$q;
        d1 = ((d_in) & 22'h3fffff);
        tp$0 = ((p_in) & 22'h3fffff);
        tx$0 = x_in;
        t$0 = tp$0 << 32'h1;
        if (tx$0[x_msb]) begin
            t$0 = (tp$0 << 32'h1) | 32'h1;
        end
        diff$0 = t$0 - d1;
        if (diff$0[borrow]) begin
            tp$1 = t$0;
            tx$1 = tx$0 << 32'h1;
        end
        else begin
            tp$1 = diff$0;
            tx$1 = (tx$0 << 32'h1) | 32'h1;
        end
        t$1 = tp$1 << 32'h1;
        if (tx$1[x_msb]) begin
            t$1 = (tp$1 << 32'h1) | 32'h1;
        end
        diff$1 = t$1 - d1;
        if (diff$1[borrow]) begin
            tp$2 = t$1;
            tx$2 = tx$1 << 32'h1;
        end
        else begin
            tp$2 = diff$1;
            tx$2 = (tx$1 << 32'h1) | 32'h1;
        end
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$2[(32'h0)+:(21)];
            x_r$d = tx$2;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$2[(32'h0)+:(21)] - 32'h1;
                x_r$d = ~tx$2;
            end
            d_r$d = d_in;
            neg_r$d = neg_in;
        end
        valid = valid_r$q;
        p = p_r$q;
        x = x_r$q;
        d = d_r$q;
        neg = neg_r$q;
    end
    
endmodule // texture_path$unit$coords$recip$stages$10


module texture_path$unit$coords$recip$stages$10$d_r(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$10$d_r


module texture_path$unit$coords$recip$stages$10$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$10$neg_r


module texture_path$unit$coords$recip$stages$10$p_r(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$10$p_r


module texture_path$unit$coords$recip$stages$10$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$10$valid_r


module texture_path$unit$coords$recip$stages$10$x_r(d,q,clock);
    
    // Module arguments
    input wire  [25:0] d;
    output reg  [25:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 26'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$10$x_r


module texture_path$unit$coords$recip$stages$11(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [20:0] p_in;
    input wire  [25:0] x_in;
    input wire  [20:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [20:0] p;
    output reg  [25:0] x;
    output reg  [20:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h15;
    localparam  x_msb = 8'h19;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [20:0] p_r$d;
    wire  [20:0] p_r$q;
    reg  p_r$clock;
    reg  [25:0] x_r$d;
    wire  [25:0] x_r$q;
    reg  x_r$clock;
    reg  [20:0] d_r$d;
    wire  [20:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [21:0] tp$0;
    reg  [21:0] tp$1;
    reg  [21:0] tp$2;
    reg  [25:0] tx$0;
    reg  [25:0] tx$1;
    reg  [25:0] tx$2;
    reg  [21:0] t$0;
    reg  [21:0] t$1;
    reg  [21:0] diff$0;
    reg  [21:0] diff$1;
    reg  [21:0] d1;
    
    // Sub module instances
    texture_path$unit$coords$recip$stages$11$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    texture_path$unit$coords$recip$stages$11$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    texture_path$unit$coords$recip$stages$11$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    texture_path$unit$coords$recip$stages$11$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    texture_path$unit$coords$recip$stages$11$neg_r neg_r(
        .d(neg_r$d),
        .q(neg_r$q),
        .clock(neg_r$clock)
    );
    
    // Update code
    always @(*) begin
        valid_r$clock = clock;
        p_r$clock = clock;
        x_r$clock = clock;
        d_r$clock = clock;
        neg_r$clock = clock;
        valid_r$d = valid_r$q;
        p_r$d = p_r$q;
        x_r$d = x_r$q;
        d_r$d = d_r$q;
        neg_r$d = neg_r$q;
        d1 = ((d_in) & 22'h3fffff);
        tp$0 = ((p_in) & 22'h3fffff);
        tx$0 = x_in;
        t$0 = tp$0 << 32'h1;
        if (tx$0[x_msb]) begin
            t$0 = (tp$0 << 32'h1) | 32'h1;
        end
        diff$0 = t$0 - d1;
        if (diff$0[borrow]) begin
            tp$1 = t$0;
            tx$1 = tx$0 << 32'h1;
        end
        else begin
            tp$1 = diff$0;
            tx$1 = (tx$0 << 32'h1) | 32'h1;
        end
        t$1 = tp$1 << 32'h1;
        if (tx$1[x_msb]) begin
            t$1 = (tp$1 << 32'h1) | 32'h1;
        end
        diff$1 = t$1 - d1;
        if (diff$1[borrow]) begin
            tp$2 = t$1;
            tx$2 = tx$1 << 32'h1;
        end
        else begin
            tp$2 = diff$1;
            tx$2 = (tx$1 << 32'h1) | 32'h1;
        end
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$2[(32'h0)+:(21)];
            x_r$d = tx$2;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$2[(32'h0)+:(21)] - 32'h1;
                x_r$d = ~tx$2;
            end
            d_r$d = d_in;
            neg_r$d = neg_in;
        end
        valid = valid_r$q;
        p = p_r$q;
        x = x_r$q;
        d = d_r$q;
        neg = neg_r$q;
    end
    
endmodule // texture_path$unit$coords$recip$stages$11


module texture_path$unit$coords$recip$stages$11$d_r(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$11$d_r


module texture_path$unit$coords$recip$stages$11$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$11$neg_r


module texture_path$unit$coords$recip$stages$11$p_r(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$11$p_r


module texture_path$unit$coords$recip$stages$11$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$11$valid_r


module texture_path$unit$coords$recip$stages$11$x_r(d,q,clock);
    
    // Module arguments
    input wire  [25:0] d;
    output reg  [25:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 26'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$11$x_r


module texture_path$unit$coords$recip$stages$12(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [20:0] p_in;
    input wire  [25:0] x_in;
    input wire  [20:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [20:0] p;
    output reg  [25:0] x;
    output reg  [20:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h15;
    localparam  x_msb = 8'h19;
    localparam  fin = 1'b1;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [20:0] p_r$d;
    wire  [20:0] p_r$q;
    reg  p_r$clock;
    reg  [25:0] x_r$d;
    wire  [25:0] x_r$q;
    reg  x_r$clock;
    reg  [20:0] d_r$d;
    wire  [20:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [21:0] tp$0;
    reg  [21:0] tp$1;
    reg  [21:0] tp$2;
    reg  [25:0] tx$0;
    reg  [25:0] tx$1;
    reg  [25:0] tx$2;
    reg  [21:0] t$0;
    reg  [21:0] t$1;
    reg  [21:0] diff$0;
    reg  [21:0] diff$1;
    reg  [21:0] d1;
    
    // Sub module instances
    texture_path$unit$coords$recip$stages$12$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    texture_path$unit$coords$recip$stages$12$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    texture_path$unit$coords$recip$stages$12$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    texture_path$unit$coords$recip$stages$12$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    texture_path$unit$coords$recip$stages$12$neg_r neg_r(
        .d(neg_r$d),
        .q(neg_r$q),
        .clock(neg_r$clock)
    );
    
    // Update code
    always @(*) begin
        valid_r$clock = clock;
        p_r$clock = clock;
        x_r$clock = clock;
        d_r$clock = clock;
        neg_r$clock = clock;
        valid_r$d = valid_r$q;
        p_r$d = p_r$q;
        x_r$d = x_r$q;
        d_r$d = d_r$q;
        neg_r$d = neg_r$q;
        d1 = ((d_in) & 22'h3fffff);
        tp$0 = ((p_in) & 22'h3fffff);
        tx$0 = x_in;
        t$0 = tp$0 << 32'h1;
        if (tx$0[x_msb]) begin
            t$0 = (tp$0 << 32'h1) | 32'h1;
        end
        diff$0 = t$0 - d1;
        if (diff$0[borrow]) begin
            tp$1 = t$0;
            tx$1 = tx$0 << 32'h1;
        end
        else begin
            tp$1 = diff$0;
            tx$1 = (tx$0 << 32'h1) | 32'h1;
        end
        t$1 = tp$1 << 32'h1;
        if (tx$1[x_msb]) begin
            t$1 = (tp$1 << 32'h1) | 32'h1;
        end
        diff$1 = t$1 - d1;
        if (diff$1[borrow]) begin
            tp$2 = t$1;
            tx$2 = tx$1 << 32'h1;
        end
        else begin
            tp$2 = diff$1;
            tx$2 = (tx$1 << 32'h1) | 32'h1;
        end
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$2[(32'h0)+:(21)];
            x_r$d = tx$2;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$2[(32'h0)+:(21)] - 32'h1;
                x_r$d = ~tx$2;
            end
            d_r$d = d_in;
            neg_r$d = neg_in;
        end
        valid = valid_r$q;
        p = p_r$q;
        x = x_r$q;
        d = d_r$q;
        neg = neg_r$q;
    end
    
endmodule // texture_path$unit$coords$recip$stages$12


module texture_path$unit$coords$recip$stages$12$d_r(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$12$d_r


module texture_path$unit$coords$recip$stages$12$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$12$neg_r


module texture_path$unit$coords$recip$stages$12$p_r(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$12$p_r


module texture_path$unit$coords$recip$stages$12$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$12$valid_r


module texture_path$unit$coords$recip$stages$12$x_r(d,q,clock);
    
    // Module arguments
    input wire  [25:0] d;
    output reg  [25:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 26'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$12$x_r


module texture_path$unit$coords$recip$stages$2(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [20:0] p_in;
    input wire  [25:0] x_in;
    input wire  [20:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [20:0] p;
    output reg  [25:0] x;
    output reg  [20:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h15;
    localparam  x_msb = 8'h19;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [20:0] p_r$d;
    wire  [20:0] p_r$q;
    reg  p_r$clock;
    reg  [25:0] x_r$d;
    wire  [25:0] x_r$q;
    reg  x_r$clock;
    reg  [20:0] d_r$d;
    wire  [20:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [21:0] tp$0;
    reg  [21:0] tp$1;
    reg  [21:0] tp$2;
    reg  [25:0] tx$0;
    reg  [25:0] tx$1;
    reg  [25:0] tx$2;
    reg  [21:0] t$0;
    reg  [21:0] t$1;
    reg  [21:0] diff$0;
    reg  [21:0] diff$1;
    reg  [21:0] d1;
    
    // Sub module instances
    texture_path$unit$coords$recip$stages$2$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    texture_path$unit$coords$recip$stages$2$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    texture_path$unit$coords$recip$stages$2$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    texture_path$unit$coords$recip$stages$2$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    texture_path$unit$coords$recip$stages$2$neg_r neg_r(
        .d(neg_r$d),
        .q(neg_r$q),
        .clock(neg_r$clock)
    );
    
    // Update code
    always @(*) begin
        valid_r$clock = clock;
        p_r$clock = clock;
        x_r$clock = clock;
        d_r$clock = clock;
        neg_r$clock = clock;
        valid_r$d = valid_r$q;
        p_r$d = p_r$q;
        x_r$d = x_r$q;
        d_r$d = d_r$q;
        neg_r$d = neg_r$q;
        d1 = ((d_in) & 22'h3fffff);
        tp$0 = ((p_in) & 22'h3fffff);
        tx$0 = x_in;
        t$0 = tp$0 << 32'h1;
        if (tx$0[x_msb]) begin
            t$0 = (tp$0 << 32'h1) | 32'h1;
        end
        diff$0 = t$0 - d1;
        if (diff$0[borrow]) begin
            tp$1 = t$0;
            tx$1 = tx$0 << 32'h1;
        end
        else begin
            tp$1 = diff$0;
            tx$1 = (tx$0 << 32'h1) | 32'h1;
        end
        t$1 = tp$1 << 32'h1;
        if (tx$1[x_msb]) begin
            t$1 = (tp$1 << 32'h1) | 32'h1;
        end
        diff$1 = t$1 - d1;
        if (diff$1[borrow]) begin
            tp$2 = t$1;
            tx$2 = tx$1 << 32'h1;
        end
        else begin
            tp$2 = diff$1;
            tx$2 = (tx$1 << 32'h1) | 32'h1;
        end
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$2[(32'h0)+:(21)];
            x_r$d = tx$2;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$2[(32'h0)+:(21)] - 32'h1;
                x_r$d = ~tx$2;
            end
            d_r$d = d_in;
            neg_r$d = neg_in;
        end
        valid = valid_r$q;
        p = p_r$q;
        x = x_r$q;
        d = d_r$q;
        neg = neg_r$q;
    end
    
endmodule // texture_path$unit$coords$recip$stages$2


module texture_path$unit$coords$recip$stages$2$d_r(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$2$d_r


module texture_path$unit$coords$recip$stages$2$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$2$neg_r


module texture_path$unit$coords$recip$stages$2$p_r(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$2$p_r


module texture_path$unit$coords$recip$stages$2$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$2$valid_r


module texture_path$unit$coords$recip$stages$2$x_r(d,q,clock);
    
    // Module arguments
    input wire  [25:0] d;
    output reg  [25:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 26'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$2$x_r


module texture_path$unit$coords$recip$stages$3(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [20:0] p_in;
    input wire  [25:0] x_in;
    input wire  [20:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [20:0] p;
    output reg  [25:0] x;
    output reg  [20:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h15;
    localparam  x_msb = 8'h19;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [20:0] p_r$d;
    wire  [20:0] p_r$q;
    reg  p_r$clock;
    reg  [25:0] x_r$d;
    wire  [25:0] x_r$q;
    reg  x_r$clock;
    reg  [20:0] d_r$d;
    wire  [20:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [21:0] tp$0;
    reg  [21:0] tp$1;
    reg  [21:0] tp$2;
    reg  [25:0] tx$0;
    reg  [25:0] tx$1;
    reg  [25:0] tx$2;
    reg  [21:0] t$0;
    reg  [21:0] t$1;
    reg  [21:0] diff$0;
    reg  [21:0] diff$1;
    reg  [21:0] d1;
    
    // Sub module instances
    texture_path$unit$coords$recip$stages$3$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    texture_path$unit$coords$recip$stages$3$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    texture_path$unit$coords$recip$stages$3$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    texture_path$unit$coords$recip$stages$3$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    texture_path$unit$coords$recip$stages$3$neg_r neg_r(
        .d(neg_r$d),
        .q(neg_r$q),
        .clock(neg_r$clock)
    );
    
    // Update code
    always @(*) begin
        valid_r$clock = clock;
        p_r$clock = clock;
        x_r$clock = clock;
        d_r$clock = clock;
        neg_r$clock = clock;
        valid_r$d = valid_r$q;
        p_r$d = p_r$q;
        x_r$d = x_r$q;
        d_r$d = d_r$q;
        neg_r$d = neg_r$q;
        d1 = ((d_in) & 22'h3fffff);
        tp$0 = ((p_in) & 22'h3fffff);
        tx$0 = x_in;
        t$0 = tp$0 << 32'h1;
        if (tx$0[x_msb]) begin
            t$0 = (tp$0 << 32'h1) | 32'h1;
        end
        diff$0 = t$0 - d1;
        if (diff$0[borrow]) begin
            tp$1 = t$0;
            tx$1 = tx$0 << 32'h1;
        end
        else begin
            tp$1 = diff$0;
            tx$1 = (tx$0 << 32'h1) | 32'h1;
        end
        t$1 = tp$1 << 32'h1;
        if (tx$1[x_msb]) begin
            t$1 = (tp$1 << 32'h1) | 32'h1;
        end
        diff$1 = t$1 - d1;
        if (diff$1[borrow]) begin
            tp$2 = t$1;
            tx$2 = tx$1 << 32'h1;
        end
        else begin
            tp$2 = diff$1;
            tx$2 = (tx$1 << 32'h1) | 32'h1;
        end
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$2[(32'h0)+:(21)];
            x_r$d = tx$2;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$2[(32'h0)+:(21)] - 32'h1;
                x_r$d = ~tx$2;
            end
            d_r$d = d_in;
            neg_r$d = neg_in;
        end
        valid = valid_r$q;
        p = p_r$q;
        x = x_r$q;
        d = d_r$q;
        neg = neg_r$q;
    end
    
endmodule // texture_path$unit$coords$recip$stages$3


module texture_path$unit$coords$recip$stages$3$d_r(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$3$d_r


module texture_path$unit$coords$recip$stages$3$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$3$neg_r


module texture_path$unit$coords$recip$stages$3$p_r(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$3$p_r


module texture_path$unit$coords$recip$stages$3$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$3$valid_r


module texture_path$unit$coords$recip$stages$3$x_r(d,q,clock);
    
    // Module arguments
    input wire  [25:0] d;
    output reg  [25:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 26'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$3$x_r


module texture_path$unit$coords$recip$stages$4(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [20:0] p_in;
    input wire  [25:0] x_in;
    input wire  [20:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [20:0] p;
    output reg  [25:0] x;
    output reg  [20:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h15;
    localparam  x_msb = 8'h19;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [20:0] p_r$d;
    wire  [20:0] p_r$q;
    reg  p_r$clock;
    reg  [25:0] x_r$d;
    wire  [25:0] x_r$q;
    reg  x_r$clock;
    reg  [20:0] d_r$d;
    wire  [20:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [21:0] tp$0;
    reg  [21:0] tp$1;
    reg  [21:0] tp$2;
    reg  [25:0] tx$0;
    reg  [25:0] tx$1;
    reg  [25:0] tx$2;
    reg  [21:0] t$0;
    reg  [21:0] t$1;
    reg  [21:0] diff$0;
    reg  [21:0] diff$1;
    reg  [21:0] d1;
    
    // Sub module instances
    texture_path$unit$coords$recip$stages$4$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    texture_path$unit$coords$recip$stages$4$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    texture_path$unit$coords$recip$stages$4$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    texture_path$unit$coords$recip$stages$4$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    texture_path$unit$coords$recip$stages$4$neg_r neg_r(
        .d(neg_r$d),
        .q(neg_r$q),
        .clock(neg_r$clock)
    );
    
    // Update code
    always @(*) begin
        valid_r$clock = clock;
        p_r$clock = clock;
        x_r$clock = clock;
        d_r$clock = clock;
        neg_r$clock = clock;
        valid_r$d = valid_r$q;
        p_r$d = p_r$q;
        x_r$d = x_r$q;
        d_r$d = d_r$q;
        neg_r$d = neg_r$q;
        d1 = ((d_in) & 22'h3fffff);
        tp$0 = ((p_in) & 22'h3fffff);
        tx$0 = x_in;
        t$0 = tp$0 << 32'h1;
        if (tx$0[x_msb]) begin
            t$0 = (tp$0 << 32'h1) | 32'h1;
        end
        diff$0 = t$0 - d1;
        if (diff$0[borrow]) begin
            tp$1 = t$0;
            tx$1 = tx$0 << 32'h1;
        end
        else begin
            tp$1 = diff$0;
            tx$1 = (tx$0 << 32'h1) | 32'h1;
        end
        t$1 = tp$1 << 32'h1;
        if (tx$1[x_msb]) begin
            t$1 = (tp$1 << 32'h1) | 32'h1;
        end
        diff$1 = t$1 - d1;
        if (diff$1[borrow]) begin
            tp$2 = t$1;
            tx$2 = tx$1 << 32'h1;
        end
        else begin
            tp$2 = diff$1;
            tx$2 = (tx$1 << 32'h1) | 32'h1;
        end
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$2[(32'h0)+:(21)];
            x_r$d = tx$2;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$2[(32'h0)+:(21)] - 32'h1;
                x_r$d = ~tx$2;
            end
            d_r$d = d_in;
            neg_r$d = neg_in;
        end
        valid = valid_r$q;
        p = p_r$q;
        x = x_r$q;
        d = d_r$q;
        neg = neg_r$q;
    end
    
endmodule // texture_path$unit$coords$recip$stages$4


module texture_path$unit$coords$recip$stages$4$d_r(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$4$d_r


module texture_path$unit$coords$recip$stages$4$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$4$neg_r


module texture_path$unit$coords$recip$stages$4$p_r(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$4$p_r


module texture_path$unit$coords$recip$stages$4$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$4$valid_r


module texture_path$unit$coords$recip$stages$4$x_r(d,q,clock);
    
    // Module arguments
    input wire  [25:0] d;
    output reg  [25:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 26'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$4$x_r


module texture_path$unit$coords$recip$stages$5(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [20:0] p_in;
    input wire  [25:0] x_in;
    input wire  [20:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [20:0] p;
    output reg  [25:0] x;
    output reg  [20:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h15;
    localparam  x_msb = 8'h19;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [20:0] p_r$d;
    wire  [20:0] p_r$q;
    reg  p_r$clock;
    reg  [25:0] x_r$d;
    wire  [25:0] x_r$q;
    reg  x_r$clock;
    reg  [20:0] d_r$d;
    wire  [20:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [21:0] tp$0;
    reg  [21:0] tp$1;
    reg  [21:0] tp$2;
    reg  [25:0] tx$0;
    reg  [25:0] tx$1;
    reg  [25:0] tx$2;
    reg  [21:0] t$0;
    reg  [21:0] t$1;
    reg  [21:0] diff$0;
    reg  [21:0] diff$1;
    reg  [21:0] d1;
    
    // Sub module instances
    texture_path$unit$coords$recip$stages$5$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    texture_path$unit$coords$recip$stages$5$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    texture_path$unit$coords$recip$stages$5$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    texture_path$unit$coords$recip$stages$5$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    texture_path$unit$coords$recip$stages$5$neg_r neg_r(
        .d(neg_r$d),
        .q(neg_r$q),
        .clock(neg_r$clock)
    );
    
    // Update code
    always @(*) begin
        valid_r$clock = clock;
        p_r$clock = clock;
        x_r$clock = clock;
        d_r$clock = clock;
        neg_r$clock = clock;
        valid_r$d = valid_r$q;
        p_r$d = p_r$q;
        x_r$d = x_r$q;
        d_r$d = d_r$q;
        neg_r$d = neg_r$q;
        d1 = ((d_in) & 22'h3fffff);
        tp$0 = ((p_in) & 22'h3fffff);
        tx$0 = x_in;
        t$0 = tp$0 << 32'h1;
        if (tx$0[x_msb]) begin
            t$0 = (tp$0 << 32'h1) | 32'h1;
        end
        diff$0 = t$0 - d1;
        if (diff$0[borrow]) begin
            tp$1 = t$0;
            tx$1 = tx$0 << 32'h1;
        end
        else begin
            tp$1 = diff$0;
            tx$1 = (tx$0 << 32'h1) | 32'h1;
        end
        t$1 = tp$1 << 32'h1;
        if (tx$1[x_msb]) begin
            t$1 = (tp$1 << 32'h1) | 32'h1;
        end
        diff$1 = t$1 - d1;
        if (diff$1[borrow]) begin
            tp$2 = t$1;
            tx$2 = tx$1 << 32'h1;
        end
        else begin
            tp$2 = diff$1;
            tx$2 = (tx$1 << 32'h1) | 32'h1;
        end
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$2[(32'h0)+:(21)];
            x_r$d = tx$2;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$2[(32'h0)+:(21)] - 32'h1;
                x_r$d = ~tx$2;
            end
            d_r$d = d_in;
            neg_r$d = neg_in;
        end
        valid = valid_r$q;
        p = p_r$q;
        x = x_r$q;
        d = d_r$q;
        neg = neg_r$q;
    end
    
endmodule // texture_path$unit$coords$recip$stages$5


module texture_path$unit$coords$recip$stages$5$d_r(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$5$d_r


module texture_path$unit$coords$recip$stages$5$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$5$neg_r


module texture_path$unit$coords$recip$stages$5$p_r(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$5$p_r


module texture_path$unit$coords$recip$stages$5$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$5$valid_r


module texture_path$unit$coords$recip$stages$5$x_r(d,q,clock);
    
    // Module arguments
    input wire  [25:0] d;
    output reg  [25:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 26'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$5$x_r


module texture_path$unit$coords$recip$stages$6(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [20:0] p_in;
    input wire  [25:0] x_in;
    input wire  [20:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [20:0] p;
    output reg  [25:0] x;
    output reg  [20:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h15;
    localparam  x_msb = 8'h19;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [20:0] p_r$d;
    wire  [20:0] p_r$q;
    reg  p_r$clock;
    reg  [25:0] x_r$d;
    wire  [25:0] x_r$q;
    reg  x_r$clock;
    reg  [20:0] d_r$d;
    wire  [20:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [21:0] tp$0;
    reg  [21:0] tp$1;
    reg  [21:0] tp$2;
    reg  [25:0] tx$0;
    reg  [25:0] tx$1;
    reg  [25:0] tx$2;
    reg  [21:0] t$0;
    reg  [21:0] t$1;
    reg  [21:0] diff$0;
    reg  [21:0] diff$1;
    reg  [21:0] d1;
    
    // Sub module instances
    texture_path$unit$coords$recip$stages$6$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    texture_path$unit$coords$recip$stages$6$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    texture_path$unit$coords$recip$stages$6$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    texture_path$unit$coords$recip$stages$6$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    texture_path$unit$coords$recip$stages$6$neg_r neg_r(
        .d(neg_r$d),
        .q(neg_r$q),
        .clock(neg_r$clock)
    );
    
    // Update code
    always @(*) begin
        valid_r$clock = clock;
        p_r$clock = clock;
        x_r$clock = clock;
        d_r$clock = clock;
        neg_r$clock = clock;
        valid_r$d = valid_r$q;
        p_r$d = p_r$q;
        x_r$d = x_r$q;
        d_r$d = d_r$q;
        neg_r$d = neg_r$q;
        d1 = ((d_in) & 22'h3fffff);
        tp$0 = ((p_in) & 22'h3fffff);
        tx$0 = x_in;
        t$0 = tp$0 << 32'h1;
        if (tx$0[x_msb]) begin
            t$0 = (tp$0 << 32'h1) | 32'h1;
        end
        diff$0 = t$0 - d1;
        if (diff$0[borrow]) begin
            tp$1 = t$0;
            tx$1 = tx$0 << 32'h1;
        end
        else begin
            tp$1 = diff$0;
            tx$1 = (tx$0 << 32'h1) | 32'h1;
        end
        t$1 = tp$1 << 32'h1;
        if (tx$1[x_msb]) begin
            t$1 = (tp$1 << 32'h1) | 32'h1;
        end
        diff$1 = t$1 - d1;
        if (diff$1[borrow]) begin
            tp$2 = t$1;
            tx$2 = tx$1 << 32'h1;
        end
        else begin
            tp$2 = diff$1;
            tx$2 = (tx$1 << 32'h1) | 32'h1;
        end
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$2[(32'h0)+:(21)];
            x_r$d = tx$2;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$2[(32'h0)+:(21)] - 32'h1;
                x_r$d = ~tx$2;
            end
            d_r$d = d_in;
            neg_r$d = neg_in;
        end
        valid = valid_r$q;
        p = p_r$q;
        x = x_r$q;
        d = d_r$q;
        neg = neg_r$q;
    end
    
endmodule // texture_path$unit$coords$recip$stages$6


module texture_path$unit$coords$recip$stages$6$d_r(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$6$d_r


module texture_path$unit$coords$recip$stages$6$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$6$neg_r


module texture_path$unit$coords$recip$stages$6$p_r(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$6$p_r


module texture_path$unit$coords$recip$stages$6$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$6$valid_r


module texture_path$unit$coords$recip$stages$6$x_r(d,q,clock);
    
    // Module arguments
    input wire  [25:0] d;
    output reg  [25:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 26'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$6$x_r


module texture_path$unit$coords$recip$stages$7(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [20:0] p_in;
    input wire  [25:0] x_in;
    input wire  [20:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [20:0] p;
    output reg  [25:0] x;
    output reg  [20:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h15;
    localparam  x_msb = 8'h19;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [20:0] p_r$d;
    wire  [20:0] p_r$q;
    reg  p_r$clock;
    reg  [25:0] x_r$d;
    wire  [25:0] x_r$q;
    reg  x_r$clock;
    reg  [20:0] d_r$d;
    wire  [20:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [21:0] tp$0;
    reg  [21:0] tp$1;
    reg  [21:0] tp$2;
    reg  [25:0] tx$0;
    reg  [25:0] tx$1;
    reg  [25:0] tx$2;
    reg  [21:0] t$0;
    reg  [21:0] t$1;
    reg  [21:0] diff$0;
    reg  [21:0] diff$1;
    reg  [21:0] d1;
    
    // Sub module instances
    texture_path$unit$coords$recip$stages$7$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    texture_path$unit$coords$recip$stages$7$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    texture_path$unit$coords$recip$stages$7$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    texture_path$unit$coords$recip$stages$7$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    texture_path$unit$coords$recip$stages$7$neg_r neg_r(
        .d(neg_r$d),
        .q(neg_r$q),
        .clock(neg_r$clock)
    );
    
    // Update code
    always @(*) begin
        valid_r$clock = clock;
        p_r$clock = clock;
        x_r$clock = clock;
        d_r$clock = clock;
        neg_r$clock = clock;
        valid_r$d = valid_r$q;
        p_r$d = p_r$q;
        x_r$d = x_r$q;
        d_r$d = d_r$q;
        neg_r$d = neg_r$q;
        d1 = ((d_in) & 22'h3fffff);
        tp$0 = ((p_in) & 22'h3fffff);
        tx$0 = x_in;
        t$0 = tp$0 << 32'h1;
        if (tx$0[x_msb]) begin
            t$0 = (tp$0 << 32'h1) | 32'h1;
        end
        diff$0 = t$0 - d1;
        if (diff$0[borrow]) begin
            tp$1 = t$0;
            tx$1 = tx$0 << 32'h1;
        end
        else begin
            tp$1 = diff$0;
            tx$1 = (tx$0 << 32'h1) | 32'h1;
        end
        t$1 = tp$1 << 32'h1;
        if (tx$1[x_msb]) begin
            t$1 = (tp$1 << 32'h1) | 32'h1;
        end
        diff$1 = t$1 - d1;
        if (diff$1[borrow]) begin
            tp$2 = t$1;
            tx$2 = tx$1 << 32'h1;
        end
        else begin
            tp$2 = diff$1;
            tx$2 = (tx$1 << 32'h1) | 32'h1;
        end
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$2[(32'h0)+:(21)];
            x_r$d = tx$2;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$2[(32'h0)+:(21)] - 32'h1;
                x_r$d = ~tx$2;
            end
            d_r$d = d_in;
            neg_r$d = neg_in;
        end
        valid = valid_r$q;
        p = p_r$q;
        x = x_r$q;
        d = d_r$q;
        neg = neg_r$q;
    end
    
endmodule // texture_path$unit$coords$recip$stages$7


module texture_path$unit$coords$recip$stages$7$d_r(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$7$d_r


module texture_path$unit$coords$recip$stages$7$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$7$neg_r


module texture_path$unit$coords$recip$stages$7$p_r(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$7$p_r


module texture_path$unit$coords$recip$stages$7$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$7$valid_r


module texture_path$unit$coords$recip$stages$7$x_r(d,q,clock);
    
    // Module arguments
    input wire  [25:0] d;
    output reg  [25:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 26'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$7$x_r


module texture_path$unit$coords$recip$stages$8(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [20:0] p_in;
    input wire  [25:0] x_in;
    input wire  [20:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [20:0] p;
    output reg  [25:0] x;
    output reg  [20:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h15;
    localparam  x_msb = 8'h19;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [20:0] p_r$d;
    wire  [20:0] p_r$q;
    reg  p_r$clock;
    reg  [25:0] x_r$d;
    wire  [25:0] x_r$q;
    reg  x_r$clock;
    reg  [20:0] d_r$d;
    wire  [20:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [21:0] tp$0;
    reg  [21:0] tp$1;
    reg  [21:0] tp$2;
    reg  [25:0] tx$0;
    reg  [25:0] tx$1;
    reg  [25:0] tx$2;
    reg  [21:0] t$0;
    reg  [21:0] t$1;
    reg  [21:0] diff$0;
    reg  [21:0] diff$1;
    reg  [21:0] d1;
    
    // Sub module instances
    texture_path$unit$coords$recip$stages$8$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    texture_path$unit$coords$recip$stages$8$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    texture_path$unit$coords$recip$stages$8$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    texture_path$unit$coords$recip$stages$8$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    texture_path$unit$coords$recip$stages$8$neg_r neg_r(
        .d(neg_r$d),
        .q(neg_r$q),
        .clock(neg_r$clock)
    );
    
    // Update code
    always @(*) begin
        valid_r$clock = clock;
        p_r$clock = clock;
        x_r$clock = clock;
        d_r$clock = clock;
        neg_r$clock = clock;
        valid_r$d = valid_r$q;
        p_r$d = p_r$q;
        x_r$d = x_r$q;
        d_r$d = d_r$q;
        neg_r$d = neg_r$q;
        d1 = ((d_in) & 22'h3fffff);
        tp$0 = ((p_in) & 22'h3fffff);
        tx$0 = x_in;
        t$0 = tp$0 << 32'h1;
        if (tx$0[x_msb]) begin
            t$0 = (tp$0 << 32'h1) | 32'h1;
        end
        diff$0 = t$0 - d1;
        if (diff$0[borrow]) begin
            tp$1 = t$0;
            tx$1 = tx$0 << 32'h1;
        end
        else begin
            tp$1 = diff$0;
            tx$1 = (tx$0 << 32'h1) | 32'h1;
        end
        t$1 = tp$1 << 32'h1;
        if (tx$1[x_msb]) begin
            t$1 = (tp$1 << 32'h1) | 32'h1;
        end
        diff$1 = t$1 - d1;
        if (diff$1[borrow]) begin
            tp$2 = t$1;
            tx$2 = tx$1 << 32'h1;
        end
        else begin
            tp$2 = diff$1;
            tx$2 = (tx$1 << 32'h1) | 32'h1;
        end
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$2[(32'h0)+:(21)];
            x_r$d = tx$2;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$2[(32'h0)+:(21)] - 32'h1;
                x_r$d = ~tx$2;
            end
            d_r$d = d_in;
            neg_r$d = neg_in;
        end
        valid = valid_r$q;
        p = p_r$q;
        x = x_r$q;
        d = d_r$q;
        neg = neg_r$q;
    end
    
endmodule // texture_path$unit$coords$recip$stages$8


module texture_path$unit$coords$recip$stages$8$d_r(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$8$d_r


module texture_path$unit$coords$recip$stages$8$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$8$neg_r


module texture_path$unit$coords$recip$stages$8$p_r(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$8$p_r


module texture_path$unit$coords$recip$stages$8$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$8$valid_r


module texture_path$unit$coords$recip$stages$8$x_r(d,q,clock);
    
    // Module arguments
    input wire  [25:0] d;
    output reg  [25:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 26'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$8$x_r


module texture_path$unit$coords$recip$stages$9(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [20:0] p_in;
    input wire  [25:0] x_in;
    input wire  [20:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [20:0] p;
    output reg  [25:0] x;
    output reg  [20:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h15;
    localparam  x_msb = 8'h19;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [20:0] p_r$d;
    wire  [20:0] p_r$q;
    reg  p_r$clock;
    reg  [25:0] x_r$d;
    wire  [25:0] x_r$q;
    reg  x_r$clock;
    reg  [20:0] d_r$d;
    wire  [20:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [21:0] tp$0;
    reg  [21:0] tp$1;
    reg  [21:0] tp$2;
    reg  [25:0] tx$0;
    reg  [25:0] tx$1;
    reg  [25:0] tx$2;
    reg  [21:0] t$0;
    reg  [21:0] t$1;
    reg  [21:0] diff$0;
    reg  [21:0] diff$1;
    reg  [21:0] d1;
    
    // Sub module instances
    texture_path$unit$coords$recip$stages$9$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    texture_path$unit$coords$recip$stages$9$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    texture_path$unit$coords$recip$stages$9$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    texture_path$unit$coords$recip$stages$9$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    texture_path$unit$coords$recip$stages$9$neg_r neg_r(
        .d(neg_r$d),
        .q(neg_r$q),
        .clock(neg_r$clock)
    );
    
    // Update code
    always @(*) begin
        valid_r$clock = clock;
        p_r$clock = clock;
        x_r$clock = clock;
        d_r$clock = clock;
        neg_r$clock = clock;
        valid_r$d = valid_r$q;
        p_r$d = p_r$q;
        x_r$d = x_r$q;
        d_r$d = d_r$q;
        neg_r$d = neg_r$q;
        d1 = ((d_in) & 22'h3fffff);
        tp$0 = ((p_in) & 22'h3fffff);
        tx$0 = x_in;
        t$0 = tp$0 << 32'h1;
        if (tx$0[x_msb]) begin
            t$0 = (tp$0 << 32'h1) | 32'h1;
        end
        diff$0 = t$0 - d1;
        if (diff$0[borrow]) begin
            tp$1 = t$0;
            tx$1 = tx$0 << 32'h1;
        end
        else begin
            tp$1 = diff$0;
            tx$1 = (tx$0 << 32'h1) | 32'h1;
        end
        t$1 = tp$1 << 32'h1;
        if (tx$1[x_msb]) begin
            t$1 = (tp$1 << 32'h1) | 32'h1;
        end
        diff$1 = t$1 - d1;
        if (diff$1[borrow]) begin
            tp$2 = t$1;
            tx$2 = tx$1 << 32'h1;
        end
        else begin
            tp$2 = diff$1;
            tx$2 = (tx$1 << 32'h1) | 32'h1;
        end
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$2[(32'h0)+:(21)];
            x_r$d = tx$2;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$2[(32'h0)+:(21)] - 32'h1;
                x_r$d = ~tx$2;
            end
            d_r$d = d_in;
            neg_r$d = neg_in;
        end
        valid = valid_r$q;
        p = p_r$q;
        x = x_r$q;
        d = d_r$q;
        neg = neg_r$q;
    end
    
endmodule // texture_path$unit$coords$recip$stages$9


module texture_path$unit$coords$recip$stages$9$d_r(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$9$d_r


module texture_path$unit$coords$recip$stages$9$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$9$neg_r


module texture_path$unit$coords$recip$stages$9$p_r(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$9$p_r


module texture_path$unit$coords$recip$stages$9$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$9$valid_r


module texture_path$unit$coords$recip$stages$9$x_r(d,q,clock);
    
    // Module arguments
    input wire  [25:0] d;
    output reg  [25:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 26'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$coords$recip$stages$9$x_r


module texture_path$unit$filter(clock,en,inp_valid,inp_words0_0,inp_words0_1,inp_words0_2,inp_words0_3,inp_words1_0,inp_words1_1,inp_words1_2,inp_words1_3,inp_alpha0,inp_beta0,inp_alpha1,inp_beta1,inp_frac,inp_two_levels,inp_format,inp_gaussian,inp_env,inp_cf,out_valid,out_rgba);
    
    // Module arguments
    input wire  clock;
    input wire  en;
    input wire  inp_valid;
    input wire  [31:0] inp_words0_0;
    input wire  [31:0] inp_words0_1;
    input wire  [31:0] inp_words0_2;
    input wire  [31:0] inp_words0_3;
    input wire  [31:0] inp_words1_0;
    input wire  [31:0] inp_words1_1;
    input wire  [31:0] inp_words1_2;
    input wire  [31:0] inp_words1_3;
    input wire  [7:0] inp_alpha0;
    input wire  [7:0] inp_beta0;
    input wire  [7:0] inp_alpha1;
    input wire  [7:0] inp_beta1;
    input wire  [5:0] inp_frac;
    input wire  inp_two_levels;
    input wire  [2:0] inp_format;
    input wire  inp_gaussian;
    input wire  [2:0] inp_env;
    input wire  [23:0] inp_cf;
    output reg  out_valid;
    output reg  [31:0] out_rgba;
    
    // Constant declarations
    localparam  decal = 3'b10;
    
    // Stub signals
    reg  [31:0] decode$0$word;
    reg  [2:0] decode$0$format;
    wire  [31:0] decode$0$rgba;
    reg  [31:0] decode$1$word;
    reg  [2:0] decode$1$format;
    wire  [31:0] decode$1$rgba;
    reg  [31:0] decode$2$word;
    reg  [2:0] decode$2$format;
    wire  [31:0] decode$2$rgba;
    reg  [31:0] decode$3$word;
    reg  [2:0] decode$3$format;
    wire  [31:0] decode$3$rgba;
    reg  [31:0] decode$4$word;
    reg  [2:0] decode$4$format;
    wire  [31:0] decode$4$rgba;
    reg  [31:0] decode$5$word;
    reg  [2:0] decode$5$format;
    wire  [31:0] decode$5$rgba;
    reg  [31:0] decode$6$word;
    reg  [2:0] decode$6$format;
    wire  [31:0] decode$6$rgba;
    reg  [31:0] decode$7$word;
    reg  [2:0] decode$7$format;
    wire  [31:0] decode$7$rgba;
    reg  [7:0] weight$0$alpha;
    reg  weight$0$gaussian;
    wire  [8:0] weight$0$w;
    reg  [7:0] weight$1$alpha;
    reg  weight$1$gaussian;
    wire  [8:0] weight$1$w;
    reg  [7:0] weight$2$alpha;
    reg  weight$2$gaussian;
    wire  [8:0] weight$2$w;
    reg  [7:0] weight$3$alpha;
    reg  weight$3$gaussian;
    wire  [8:0] weight$3$w;
    reg  [31:0] s1_texel$0$d;
    wire  [31:0] s1_texel$0$q;
    reg  s1_texel$0$clock;
    reg  [31:0] s1_texel$1$d;
    wire  [31:0] s1_texel$1$q;
    reg  s1_texel$1$clock;
    reg  [31:0] s1_texel$2$d;
    wire  [31:0] s1_texel$2$q;
    reg  s1_texel$2$clock;
    reg  [31:0] s1_texel$3$d;
    wire  [31:0] s1_texel$3$q;
    reg  s1_texel$3$clock;
    reg  [31:0] s1_texel$4$d;
    wire  [31:0] s1_texel$4$q;
    reg  s1_texel$4$clock;
    reg  [31:0] s1_texel$5$d;
    wire  [31:0] s1_texel$5$q;
    reg  s1_texel$5$clock;
    reg  [31:0] s1_texel$6$d;
    wire  [31:0] s1_texel$6$q;
    reg  s1_texel$6$clock;
    reg  [31:0] s1_texel$7$d;
    wire  [31:0] s1_texel$7$q;
    reg  s1_texel$7$clock;
    reg  [8:0] s1_a$0$d;
    wire  [8:0] s1_a$0$q;
    reg  s1_a$0$clock;
    reg  [8:0] s1_a$1$d;
    wire  [8:0] s1_a$1$q;
    reg  s1_a$1$clock;
    reg  [8:0] s1_b$0$d;
    wire  [8:0] s1_b$0$q;
    reg  s1_b$0$clock;
    reg  [8:0] s1_b$1$d;
    wire  [8:0] s1_b$1$q;
    reg  s1_b$1$clock;
    reg  [5:0] s1_frac$d;
    wire  [5:0] s1_frac$q;
    reg  s1_frac$clock;
    reg  s1_two$d;
    wire  s1_two$q;
    reg  s1_two$clock;
    reg  [2:0] s1_env$d;
    wire  [2:0] s1_env$q;
    reg  s1_env$clock;
    reg  [23:0] s1_cf$d;
    wire  [23:0] s1_cf$q;
    reg  s1_cf$clock;
    reg  s1_valid$d;
    wire  s1_valid$q;
    reg  s1_valid$clock;
    reg  level$0$clock;
    reg  level$0$en;
    reg  [31:0] level$0$t0;
    reg  [31:0] level$0$t1;
    reg  [31:0] level$0$t2;
    reg  [31:0] level$0$t3;
    reg  [8:0] level$0$a;
    reg  [8:0] level$0$b;
    wire  [31:0] level$0$c;
    reg  level$1$clock;
    reg  level$1$en;
    reg  [31:0] level$1$t0;
    reg  [31:0] level$1$t1;
    reg  [31:0] level$1$t2;
    reg  [31:0] level$1$t3;
    reg  [8:0] level$1$a;
    reg  [8:0] level$1$b;
    wire  [31:0] level$1$c;
    reg  [5:0] s2_frac$d;
    wire  [5:0] s2_frac$q;
    reg  s2_frac$clock;
    reg  s2_two$d;
    wire  s2_two$q;
    reg  s2_two$clock;
    reg  [2:0] s2_env$d;
    wire  [2:0] s2_env$q;
    reg  s2_env$clock;
    reg  [23:0] s2_cf$d;
    wire  [23:0] s2_cf$q;
    reg  s2_cf$clock;
    reg  s2_valid$d;
    wire  s2_valid$q;
    reg  s2_valid$clock;
    reg  [5:0] s3_frac$d;
    wire  [5:0] s3_frac$q;
    reg  s3_frac$clock;
    reg  s3_two$d;
    wire  s3_two$q;
    reg  s3_two$clock;
    reg  [2:0] s3_env$d;
    wire  [2:0] s3_env$q;
    reg  s3_env$clock;
    reg  [23:0] s3_cf$d;
    wire  [23:0] s3_cf$q;
    reg  s3_cf$clock;
    reg  s3_valid$d;
    wire  s3_valid$q;
    reg  s3_valid$clock;
    reg  [7:0] mix$0$x0;
    reg  [7:0] mix$0$x1;
    reg  [6:0] mix$0$w;
    wire  [13:0] mix$0$y;
    reg  [7:0] mix$1$x0;
    reg  [7:0] mix$1$x1;
    reg  [6:0] mix$1$w;
    wire  [13:0] mix$1$y;
    reg  [7:0] mix$2$x0;
    reg  [7:0] mix$2$x1;
    reg  [6:0] mix$2$w;
    wire  [13:0] mix$2$y;
    reg  [7:0] mix$3$x0;
    reg  [7:0] mix$3$x1;
    reg  [6:0] mix$3$w;
    wire  [13:0] mix$3$y;
    reg  [13:0] mix_round$0$x;
    wire  [7:0] mix_round$0$y;
    reg  [13:0] mix_round$1$x;
    wire  [7:0] mix_round$1$y;
    reg  [13:0] mix_round$2$x;
    wire  [7:0] mix_round$2$y;
    reg  [13:0] mix_round$3$x;
    wire  [7:0] mix_round$3$y;
    reg  [7:0] s4_cs$0$d;
    wire  [7:0] s4_cs$0$q;
    reg  s4_cs$0$clock;
    reg  [7:0] s4_cs$1$d;
    wire  [7:0] s4_cs$1$q;
    reg  s4_cs$1$clock;
    reg  [7:0] s4_cs$2$d;
    wire  [7:0] s4_cs$2$q;
    reg  s4_cs$2$clock;
    reg  [7:0] s4_cs$3$d;
    wire  [7:0] s4_cs$3$q;
    reg  s4_cs$3$clock;
    reg  [2:0] s4_env$d;
    wire  [2:0] s4_env$q;
    reg  s4_env$clock;
    reg  [23:0] s4_cf$d;
    wire  [23:0] s4_cf$q;
    reg  s4_cf$clock;
    reg  s4_valid$d;
    wire  s4_valid$q;
    reg  s4_valid$clock;
    reg  [7:0] environment$0$cf;
    reg  [7:0] environment$0$cs;
    reg  [7:0] environment$0$a_s;
    reg  [2:0] environment$0$mode;
    wire  [7:0] environment$0$out;
    reg  [7:0] environment$1$cf;
    reg  [7:0] environment$1$cs;
    reg  [7:0] environment$1$a_s;
    reg  [2:0] environment$1$mode;
    wire  [7:0] environment$1$out;
    reg  [7:0] environment$2$cf;
    reg  [7:0] environment$2$cs;
    reg  [7:0] environment$2$a_s;
    reg  [2:0] environment$2$mode;
    wire  [7:0] environment$2$out;
    reg  [31:0] s5_rgba$d;
    wire  [31:0] s5_rgba$q;
    reg  s5_rgba$clock;
    reg  s5_valid$d;
    wire  s5_valid$q;
    reg  s5_valid$clock;
    
    // Local signals
    reg  [6:0] mix_w;
    reg  [7:0] alpha;
    
    // Sub module instances
    texture_path$unit$filter$decode$0 decode$0(
        .word(decode$0$word),
        .format(decode$0$format),
        .rgba(decode$0$rgba)
    );
    texture_path$unit$filter$decode$1 decode$1(
        .word(decode$1$word),
        .format(decode$1$format),
        .rgba(decode$1$rgba)
    );
    texture_path$unit$filter$decode$2 decode$2(
        .word(decode$2$word),
        .format(decode$2$format),
        .rgba(decode$2$rgba)
    );
    texture_path$unit$filter$decode$3 decode$3(
        .word(decode$3$word),
        .format(decode$3$format),
        .rgba(decode$3$rgba)
    );
    texture_path$unit$filter$decode$4 decode$4(
        .word(decode$4$word),
        .format(decode$4$format),
        .rgba(decode$4$rgba)
    );
    texture_path$unit$filter$decode$5 decode$5(
        .word(decode$5$word),
        .format(decode$5$format),
        .rgba(decode$5$rgba)
    );
    texture_path$unit$filter$decode$6 decode$6(
        .word(decode$6$word),
        .format(decode$6$format),
        .rgba(decode$6$rgba)
    );
    texture_path$unit$filter$decode$7 decode$7(
        .word(decode$7$word),
        .format(decode$7$format),
        .rgba(decode$7$rgba)
    );
    texture_path$unit$filter$weight$0 weight$0(
        .alpha(weight$0$alpha),
        .gaussian(weight$0$gaussian),
        .w(weight$0$w)
    );
    texture_path$unit$filter$weight$1 weight$1(
        .alpha(weight$1$alpha),
        .gaussian(weight$1$gaussian),
        .w(weight$1$w)
    );
    texture_path$unit$filter$weight$2 weight$2(
        .alpha(weight$2$alpha),
        .gaussian(weight$2$gaussian),
        .w(weight$2$w)
    );
    texture_path$unit$filter$weight$3 weight$3(
        .alpha(weight$3$alpha),
        .gaussian(weight$3$gaussian),
        .w(weight$3$w)
    );
    texture_path$unit$filter$s1_texel$0 s1_texel$0(
        .d(s1_texel$0$d),
        .q(s1_texel$0$q),
        .clock(s1_texel$0$clock)
    );
    texture_path$unit$filter$s1_texel$1 s1_texel$1(
        .d(s1_texel$1$d),
        .q(s1_texel$1$q),
        .clock(s1_texel$1$clock)
    );
    texture_path$unit$filter$s1_texel$2 s1_texel$2(
        .d(s1_texel$2$d),
        .q(s1_texel$2$q),
        .clock(s1_texel$2$clock)
    );
    texture_path$unit$filter$s1_texel$3 s1_texel$3(
        .d(s1_texel$3$d),
        .q(s1_texel$3$q),
        .clock(s1_texel$3$clock)
    );
    texture_path$unit$filter$s1_texel$4 s1_texel$4(
        .d(s1_texel$4$d),
        .q(s1_texel$4$q),
        .clock(s1_texel$4$clock)
    );
    texture_path$unit$filter$s1_texel$5 s1_texel$5(
        .d(s1_texel$5$d),
        .q(s1_texel$5$q),
        .clock(s1_texel$5$clock)
    );
    texture_path$unit$filter$s1_texel$6 s1_texel$6(
        .d(s1_texel$6$d),
        .q(s1_texel$6$q),
        .clock(s1_texel$6$clock)
    );
    texture_path$unit$filter$s1_texel$7 s1_texel$7(
        .d(s1_texel$7$d),
        .q(s1_texel$7$q),
        .clock(s1_texel$7$clock)
    );
    texture_path$unit$filter$s1_a$0 s1_a$0(
        .d(s1_a$0$d),
        .q(s1_a$0$q),
        .clock(s1_a$0$clock)
    );
    texture_path$unit$filter$s1_a$1 s1_a$1(
        .d(s1_a$1$d),
        .q(s1_a$1$q),
        .clock(s1_a$1$clock)
    );
    texture_path$unit$filter$s1_b$0 s1_b$0(
        .d(s1_b$0$d),
        .q(s1_b$0$q),
        .clock(s1_b$0$clock)
    );
    texture_path$unit$filter$s1_b$1 s1_b$1(
        .d(s1_b$1$d),
        .q(s1_b$1$q),
        .clock(s1_b$1$clock)
    );
    texture_path$unit$filter$s1_frac s1_frac(
        .d(s1_frac$d),
        .q(s1_frac$q),
        .clock(s1_frac$clock)
    );
    texture_path$unit$filter$s1_two s1_two(
        .d(s1_two$d),
        .q(s1_two$q),
        .clock(s1_two$clock)
    );
    texture_path$unit$filter$s1_env s1_env(
        .d(s1_env$d),
        .q(s1_env$q),
        .clock(s1_env$clock)
    );
    texture_path$unit$filter$s1_cf s1_cf(
        .d(s1_cf$d),
        .q(s1_cf$q),
        .clock(s1_cf$clock)
    );
    texture_path$unit$filter$s1_valid s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    texture_path$unit$filter$level$0 level$0(
        .clock(level$0$clock),
        .en(level$0$en),
        .t0(level$0$t0),
        .t1(level$0$t1),
        .t2(level$0$t2),
        .t3(level$0$t3),
        .a(level$0$a),
        .b(level$0$b),
        .c(level$0$c)
    );
    texture_path$unit$filter$level$1 level$1(
        .clock(level$1$clock),
        .en(level$1$en),
        .t0(level$1$t0),
        .t1(level$1$t1),
        .t2(level$1$t2),
        .t3(level$1$t3),
        .a(level$1$a),
        .b(level$1$b),
        .c(level$1$c)
    );
    texture_path$unit$filter$s2_frac s2_frac(
        .d(s2_frac$d),
        .q(s2_frac$q),
        .clock(s2_frac$clock)
    );
    texture_path$unit$filter$s2_two s2_two(
        .d(s2_two$d),
        .q(s2_two$q),
        .clock(s2_two$clock)
    );
    texture_path$unit$filter$s2_env s2_env(
        .d(s2_env$d),
        .q(s2_env$q),
        .clock(s2_env$clock)
    );
    texture_path$unit$filter$s2_cf s2_cf(
        .d(s2_cf$d),
        .q(s2_cf$q),
        .clock(s2_cf$clock)
    );
    texture_path$unit$filter$s2_valid s2_valid(
        .d(s2_valid$d),
        .q(s2_valid$q),
        .clock(s2_valid$clock)
    );
    texture_path$unit$filter$s3_frac s3_frac(
        .d(s3_frac$d),
        .q(s3_frac$q),
        .clock(s3_frac$clock)
    );
    texture_path$unit$filter$s3_two s3_two(
        .d(s3_two$d),
        .q(s3_two$q),
        .clock(s3_two$clock)
    );
    texture_path$unit$filter$s3_env s3_env(
        .d(s3_env$d),
        .q(s3_env$q),
        .clock(s3_env$clock)
    );
    texture_path$unit$filter$s3_cf s3_cf(
        .d(s3_cf$d),
        .q(s3_cf$q),
        .clock(s3_cf$clock)
    );
    texture_path$unit$filter$s3_valid s3_valid(
        .d(s3_valid$d),
        .q(s3_valid$q),
        .clock(s3_valid$clock)
    );
    texture_path$unit$filter$mix$0 mix$0(
        .x0(mix$0$x0),
        .x1(mix$0$x1),
        .w(mix$0$w),
        .y(mix$0$y)
    );
    texture_path$unit$filter$mix$1 mix$1(
        .x0(mix$1$x0),
        .x1(mix$1$x1),
        .w(mix$1$w),
        .y(mix$1$y)
    );
    texture_path$unit$filter$mix$2 mix$2(
        .x0(mix$2$x0),
        .x1(mix$2$x1),
        .w(mix$2$w),
        .y(mix$2$y)
    );
    texture_path$unit$filter$mix$3 mix$3(
        .x0(mix$3$x0),
        .x1(mix$3$x1),
        .w(mix$3$w),
        .y(mix$3$y)
    );
    texture_path$unit$filter$mix_round$0 mix_round$0(
        .x(mix_round$0$x),
        .y(mix_round$0$y)
    );
    texture_path$unit$filter$mix_round$1 mix_round$1(
        .x(mix_round$1$x),
        .y(mix_round$1$y)
    );
    texture_path$unit$filter$mix_round$2 mix_round$2(
        .x(mix_round$2$x),
        .y(mix_round$2$y)
    );
    texture_path$unit$filter$mix_round$3 mix_round$3(
        .x(mix_round$3$x),
        .y(mix_round$3$y)
    );
    texture_path$unit$filter$s4_cs$0 s4_cs$0(
        .d(s4_cs$0$d),
        .q(s4_cs$0$q),
        .clock(s4_cs$0$clock)
    );
    texture_path$unit$filter$s4_cs$1 s4_cs$1(
        .d(s4_cs$1$d),
        .q(s4_cs$1$q),
        .clock(s4_cs$1$clock)
    );
    texture_path$unit$filter$s4_cs$2 s4_cs$2(
        .d(s4_cs$2$d),
        .q(s4_cs$2$q),
        .clock(s4_cs$2$clock)
    );
    texture_path$unit$filter$s4_cs$3 s4_cs$3(
        .d(s4_cs$3$d),
        .q(s4_cs$3$q),
        .clock(s4_cs$3$clock)
    );
    texture_path$unit$filter$s4_env s4_env(
        .d(s4_env$d),
        .q(s4_env$q),
        .clock(s4_env$clock)
    );
    texture_path$unit$filter$s4_cf s4_cf(
        .d(s4_cf$d),
        .q(s4_cf$q),
        .clock(s4_cf$clock)
    );
    texture_path$unit$filter$s4_valid s4_valid(
        .d(s4_valid$d),
        .q(s4_valid$q),
        .clock(s4_valid$clock)
    );
    texture_path$unit$filter$environment$0 environment$0(
        .cf(environment$0$cf),
        .cs(environment$0$cs),
        .a_s(environment$0$a_s),
        .mode(environment$0$mode),
        .out(environment$0$out)
    );
    texture_path$unit$filter$environment$1 environment$1(
        .cf(environment$1$cf),
        .cs(environment$1$cs),
        .a_s(environment$1$a_s),
        .mode(environment$1$mode),
        .out(environment$1$out)
    );
    texture_path$unit$filter$environment$2 environment$2(
        .cf(environment$2$cf),
        .cs(environment$2$cs),
        .a_s(environment$2$a_s),
        .mode(environment$2$mode),
        .out(environment$2$out)
    );
    texture_path$unit$filter$s5_rgba s5_rgba(
        .d(s5_rgba$d),
        .q(s5_rgba$q),
        .clock(s5_rgba$clock)
    );
    texture_path$unit$filter$s5_valid s5_valid(
        .d(s5_valid$d),
        .q(s5_valid$q),
        .clock(s5_valid$clock)
    );
    
    // Update code
    always @(*) begin
        s1_frac$clock = clock;
        s1_two$clock = clock;
        s1_env$clock = clock;
        s1_cf$clock = clock;
        s1_valid$clock = clock;
        s2_frac$clock = clock;
        s2_two$clock = clock;
        s2_env$clock = clock;
        s2_cf$clock = clock;
        s2_valid$clock = clock;
        s3_frac$clock = clock;
        s3_two$clock = clock;
        s3_env$clock = clock;
        s3_cf$clock = clock;
        s3_valid$clock = clock;
        s4_env$clock = clock;
        s4_cf$clock = clock;
        s4_valid$clock = clock;
        s5_rgba$clock = clock;
        s5_valid$clock = clock;
        s1_frac$d = s1_frac$q;
        s1_two$d = s1_two$q;
        s1_env$d = s1_env$q;
        s1_cf$d = s1_cf$q;
        s1_valid$d = s1_valid$q;
        s2_frac$d = s2_frac$q;
        s2_two$d = s2_two$q;
        s2_env$d = s2_env$q;
        s2_cf$d = s2_cf$q;
        s2_valid$d = s2_valid$q;
        s3_frac$d = s3_frac$q;
        s3_two$d = s3_two$q;
        s3_env$d = s3_env$q;
        s3_cf$d = s3_cf$q;
        s3_valid$d = s3_valid$q;
        s4_env$d = s4_env$q;
        s4_cf$d = s4_cf$q;
        s4_valid$d = s4_valid$q;
        s5_rgba$d = s5_rgba$q;
        s5_valid$d = s5_valid$q;
        s1_texel$0$clock = clock;
        s1_texel$0$d = s1_texel$0$q;
        s1_texel$1$clock = clock;
        s1_texel$1$d = s1_texel$1$q;
        s1_texel$2$clock = clock;
        s1_texel$2$d = s1_texel$2$q;
        s1_texel$3$clock = clock;
        s1_texel$3$d = s1_texel$3$q;
        s1_texel$4$clock = clock;
        s1_texel$4$d = s1_texel$4$q;
        s1_texel$5$clock = clock;
        s1_texel$5$d = s1_texel$5$q;
        s1_texel$6$clock = clock;
        s1_texel$6$d = s1_texel$6$q;
        s1_texel$7$clock = clock;
        s1_texel$7$d = s1_texel$7$q;
        s1_a$0$clock = clock;
        s1_a$0$d = s1_a$0$q;
        s1_b$0$clock = clock;
        s1_b$0$d = s1_b$0$q;
        level$0$clock = clock;
        level$0$en = en;
        s1_a$1$clock = clock;
        s1_a$1$d = s1_a$1$q;
        s1_b$1$clock = clock;
        s1_b$1$d = s1_b$1$q;
        level$1$clock = clock;
        level$1$en = en;
        s4_cs$0$clock = clock;
        s4_cs$0$d = s4_cs$0$q;
        s4_cs$1$clock = clock;
        s4_cs$1$d = s4_cs$1$q;
        s4_cs$2$clock = clock;
        s4_cs$2$d = s4_cs$2$q;
        s4_cs$3$clock = clock;
        s4_cs$3$d = s4_cs$3$q;
        decode$0$word = inp_words0_0;
        decode$1$word = inp_words0_1;
        decode$2$word = inp_words0_2;
        decode$3$word = inp_words0_3;
        decode$4$word = inp_words1_0;
        decode$5$word = inp_words1_1;
        decode$6$word = inp_words1_2;
        decode$7$word = inp_words1_3;
        decode$0$format = inp_format;
        decode$1$format = inp_format;
        decode$2$format = inp_format;
        decode$3$format = inp_format;
        decode$4$format = inp_format;
        decode$5$format = inp_format;
        decode$6$format = inp_format;
        decode$7$format = inp_format;
        weight$0$alpha = inp_alpha0;
        weight$1$alpha = inp_beta0;
        weight$2$alpha = inp_alpha1;
        weight$3$alpha = inp_beta1;
        weight$0$gaussian = inp_gaussian;
        weight$1$gaussian = inp_gaussian;
        weight$2$gaussian = inp_gaussian;
        weight$3$gaussian = inp_gaussian;
        level$0$a = s1_a$0$q;
        level$0$b = s1_b$0$q;
        level$1$a = s1_a$1$q;
        level$1$b = s1_b$1$q;
        level$0$t0 = s1_texel$0$q;
        level$0$t1 = s1_texel$1$q;
        level$0$t2 = s1_texel$2$q;
        level$0$t3 = s1_texel$3$q;
        level$1$t0 = s1_texel$4$q;
        level$1$t1 = s1_texel$5$q;
        level$1$t2 = s1_texel$6$q;
        level$1$t3 = s1_texel$7$q;
        mix_w = 32'h0;
        if (s3_two$q) begin
            mix_w = ((s3_frac$q) & 7'h7f);
        end
        mix$0$x0 = level$0$c[(0 * 32'h8)+:(8)];
        mix$0$x1 = level$1$c[(0 * 32'h8)+:(8)];
        mix$0$w = mix_w;
        mix_round$0$x = mix$0$y;
        mix$1$x0 = level$0$c[(1 * 32'h8)+:(8)];
        mix$1$x1 = level$1$c[(1 * 32'h8)+:(8)];
        mix$1$w = mix_w;
        mix_round$1$x = mix$1$y;
        mix$2$x0 = level$0$c[(2 * 32'h8)+:(8)];
        mix$2$x1 = level$1$c[(2 * 32'h8)+:(8)];
        mix$2$w = mix_w;
        mix_round$2$x = mix$2$y;
        mix$3$x0 = level$0$c[(3 * 32'h8)+:(8)];
        mix$3$x1 = level$1$c[(3 * 32'h8)+:(8)];
        mix$3$w = mix_w;
        mix_round$3$x = mix$3$y;
        environment$0$cf = s4_cf$q[(32'h10)+:(8)];
        environment$0$cs = s4_cs$3$q;
        environment$1$cf = s4_cf$q[(32'h8)+:(8)];
        environment$1$cs = s4_cs$2$q;
        environment$2$cf = s4_cf$q[(32'h0)+:(8)];
        environment$2$cs = s4_cs$1$q;
        environment$0$a_s = s4_cs$0$q;
        environment$0$mode = s4_env$q;
        environment$1$a_s = s4_cs$0$q;
        environment$1$mode = s4_env$q;
        environment$2$a_s = s4_cs$0$q;
        environment$2$mode = s4_env$q;
        alpha = s4_cs$0$q;
        if (s4_env$q == decal) begin
            alpha = 32'hff;
        end
        if (en) begin
            s1_texel$0$d = decode$0$rgba;
            s1_texel$1$d = decode$1$rgba;
            s1_texel$2$d = decode$2$rgba;
            s1_texel$3$d = decode$3$rgba;
            s1_texel$4$d = decode$4$rgba;
            s1_texel$5$d = decode$5$rgba;
            s1_texel$6$d = decode$6$rgba;
            s1_texel$7$d = decode$7$rgba;
            s1_a$0$d = weight$0$w;
            s1_b$0$d = weight$1$w;
            s1_a$1$d = weight$2$w;
            s1_b$1$d = weight$3$w;
            s1_frac$d = inp_frac;
            s1_two$d = inp_two_levels;
            s1_env$d = inp_env;
            s1_cf$d = inp_cf;
            s1_valid$d = inp_valid;
            s2_frac$d = s1_frac$q;
            s2_two$d = s1_two$q;
            s2_env$d = s1_env$q;
            s2_cf$d = s1_cf$q;
            s2_valid$d = s1_valid$q;
            s3_frac$d = s2_frac$q;
            s3_two$d = s2_two$q;
            s3_env$d = s2_env$q;
            s3_cf$d = s2_cf$q;
            s3_valid$d = s2_valid$q;
            s4_cs$0$d = mix_round$0$y;
            s4_cs$1$d = mix_round$1$y;
            s4_cs$2$d = mix_round$2$y;
            s4_cs$3$d = mix_round$3$y;
            s4_env$d = s3_env$q;
            s4_cf$d = s3_cf$q;
            s4_valid$d = s3_valid$q;
            s5_rgba$d = (((environment$0$out) & 32'hffffffff) << 32'h18) | (((environment$1$out) & 32'hffffffff) << 32'h10) | (((environment$2$out) & 32'hffffffff) << 32'h8) | ((alpha) & 32'hffffffff);
            s5_valid$d = s4_valid$q;
        end
        out_valid = s5_valid$q;
        out_rgba = s5_rgba$q;
    end
    
endmodule // texture_path$unit$filter


module texture_path$unit$filter$decode$0(word,format,rgba);
    
    // Module arguments
    input wire  [31:0] word;
    input wire  [2:0] format;
    output reg  [31:0] rgba;
    
    // Constant declarations
    localparam  rgb565 = 3'b0;
    localparam  rgba5551 = 3'b1;
    localparam  rgba4444 = 3'b10;
    localparam  rgb888 = 3'b11;
    
    // Local signals
    reg  [4:0] c5r;
    reg  [4:0] c5g;
    reg  [5:0] c6g;
    reg  [7:0] r;
    reg  [7:0] g;
    reg  [7:0] b;
    reg  [7:0] a;
    
    // Update code
    always @(*) begin
        c5r = word[(32'hb)+:(5)];
        c5g = word[(32'h6)+:(5)];
        c6g = word[(32'h5)+:(6)];
        r = word[(32'h18)+:(8)];
        g = word[(32'h10)+:(8)];
        b = word[(32'h8)+:(8)];
        a = word[(32'h0)+:(8)];
        if (format == rgb565) begin
            r = (((c5r) & 8'hff) << 32'h3) | ((c5r[(32'h2)+:(3)]) & 8'hff);
            g = (((c6g) & 8'hff) << 32'h2) | ((c6g[(32'h4)+:(2)]) & 8'hff);
            b = (((word[(32'h0)+:(5)]) & 8'hff) << 32'h3) | ((word[(32'h2)+:(3)]) & 8'hff);
            a = 32'hff;
        end
        if (format == rgba5551) begin
            r = (((c5r) & 8'hff) << 32'h3) | ((c5r[(32'h2)+:(3)]) & 8'hff);
            g = (((c5g) & 8'hff) << 32'h3) | ((c5g[(32'h2)+:(3)]) & 8'hff);
            b = (((word[(32'h1)+:(5)]) & 8'hff) << 32'h3) | ((word[(32'h3)+:(3)]) & 8'hff);
            a = 32'h0;
            if (word[32'h0]) begin
                a = 32'hff;
            end
        end
        if (format == rgba4444) begin
            r = (((word[(32'hc)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'hc)+:(4)]) & 8'hff);
            g = (((word[(32'h8)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'h8)+:(4)]) & 8'hff);
            b = (((word[(32'h4)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'h4)+:(4)]) & 8'hff);
            a = (((word[(32'h0)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'h0)+:(4)]) & 8'hff);
        end
        if (format == rgb888) begin
            r = word[(32'h10)+:(8)];
            g = word[(32'h8)+:(8)];
            b = word[(32'h0)+:(8)];
            a = 32'hff;
        end
        rgba = (((r) & 32'hffffffff) << 32'h18) | (((g) & 32'hffffffff) << 32'h10) | (((b) & 32'hffffffff) << 32'h8) | ((a) & 32'hffffffff);
    end
    
endmodule // texture_path$unit$filter$decode$0


module texture_path$unit$filter$decode$1(word,format,rgba);
    
    // Module arguments
    input wire  [31:0] word;
    input wire  [2:0] format;
    output reg  [31:0] rgba;
    
    // Constant declarations
    localparam  rgb565 = 3'b0;
    localparam  rgba5551 = 3'b1;
    localparam  rgba4444 = 3'b10;
    localparam  rgb888 = 3'b11;
    
    // Local signals
    reg  [4:0] c5r;
    reg  [4:0] c5g;
    reg  [5:0] c6g;
    reg  [7:0] r;
    reg  [7:0] g;
    reg  [7:0] b;
    reg  [7:0] a;
    
    // Update code
    always @(*) begin
        c5r = word[(32'hb)+:(5)];
        c5g = word[(32'h6)+:(5)];
        c6g = word[(32'h5)+:(6)];
        r = word[(32'h18)+:(8)];
        g = word[(32'h10)+:(8)];
        b = word[(32'h8)+:(8)];
        a = word[(32'h0)+:(8)];
        if (format == rgb565) begin
            r = (((c5r) & 8'hff) << 32'h3) | ((c5r[(32'h2)+:(3)]) & 8'hff);
            g = (((c6g) & 8'hff) << 32'h2) | ((c6g[(32'h4)+:(2)]) & 8'hff);
            b = (((word[(32'h0)+:(5)]) & 8'hff) << 32'h3) | ((word[(32'h2)+:(3)]) & 8'hff);
            a = 32'hff;
        end
        if (format == rgba5551) begin
            r = (((c5r) & 8'hff) << 32'h3) | ((c5r[(32'h2)+:(3)]) & 8'hff);
            g = (((c5g) & 8'hff) << 32'h3) | ((c5g[(32'h2)+:(3)]) & 8'hff);
            b = (((word[(32'h1)+:(5)]) & 8'hff) << 32'h3) | ((word[(32'h3)+:(3)]) & 8'hff);
            a = 32'h0;
            if (word[32'h0]) begin
                a = 32'hff;
            end
        end
        if (format == rgba4444) begin
            r = (((word[(32'hc)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'hc)+:(4)]) & 8'hff);
            g = (((word[(32'h8)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'h8)+:(4)]) & 8'hff);
            b = (((word[(32'h4)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'h4)+:(4)]) & 8'hff);
            a = (((word[(32'h0)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'h0)+:(4)]) & 8'hff);
        end
        if (format == rgb888) begin
            r = word[(32'h10)+:(8)];
            g = word[(32'h8)+:(8)];
            b = word[(32'h0)+:(8)];
            a = 32'hff;
        end
        rgba = (((r) & 32'hffffffff) << 32'h18) | (((g) & 32'hffffffff) << 32'h10) | (((b) & 32'hffffffff) << 32'h8) | ((a) & 32'hffffffff);
    end
    
endmodule // texture_path$unit$filter$decode$1


module texture_path$unit$filter$decode$2(word,format,rgba);
    
    // Module arguments
    input wire  [31:0] word;
    input wire  [2:0] format;
    output reg  [31:0] rgba;
    
    // Constant declarations
    localparam  rgb565 = 3'b0;
    localparam  rgba5551 = 3'b1;
    localparam  rgba4444 = 3'b10;
    localparam  rgb888 = 3'b11;
    
    // Local signals
    reg  [4:0] c5r;
    reg  [4:0] c5g;
    reg  [5:0] c6g;
    reg  [7:0] r;
    reg  [7:0] g;
    reg  [7:0] b;
    reg  [7:0] a;
    
    // Update code
    always @(*) begin
        c5r = word[(32'hb)+:(5)];
        c5g = word[(32'h6)+:(5)];
        c6g = word[(32'h5)+:(6)];
        r = word[(32'h18)+:(8)];
        g = word[(32'h10)+:(8)];
        b = word[(32'h8)+:(8)];
        a = word[(32'h0)+:(8)];
        if (format == rgb565) begin
            r = (((c5r) & 8'hff) << 32'h3) | ((c5r[(32'h2)+:(3)]) & 8'hff);
            g = (((c6g) & 8'hff) << 32'h2) | ((c6g[(32'h4)+:(2)]) & 8'hff);
            b = (((word[(32'h0)+:(5)]) & 8'hff) << 32'h3) | ((word[(32'h2)+:(3)]) & 8'hff);
            a = 32'hff;
        end
        if (format == rgba5551) begin
            r = (((c5r) & 8'hff) << 32'h3) | ((c5r[(32'h2)+:(3)]) & 8'hff);
            g = (((c5g) & 8'hff) << 32'h3) | ((c5g[(32'h2)+:(3)]) & 8'hff);
            b = (((word[(32'h1)+:(5)]) & 8'hff) << 32'h3) | ((word[(32'h3)+:(3)]) & 8'hff);
            a = 32'h0;
            if (word[32'h0]) begin
                a = 32'hff;
            end
        end
        if (format == rgba4444) begin
            r = (((word[(32'hc)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'hc)+:(4)]) & 8'hff);
            g = (((word[(32'h8)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'h8)+:(4)]) & 8'hff);
            b = (((word[(32'h4)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'h4)+:(4)]) & 8'hff);
            a = (((word[(32'h0)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'h0)+:(4)]) & 8'hff);
        end
        if (format == rgb888) begin
            r = word[(32'h10)+:(8)];
            g = word[(32'h8)+:(8)];
            b = word[(32'h0)+:(8)];
            a = 32'hff;
        end
        rgba = (((r) & 32'hffffffff) << 32'h18) | (((g) & 32'hffffffff) << 32'h10) | (((b) & 32'hffffffff) << 32'h8) | ((a) & 32'hffffffff);
    end
    
endmodule // texture_path$unit$filter$decode$2


module texture_path$unit$filter$decode$3(word,format,rgba);
    
    // Module arguments
    input wire  [31:0] word;
    input wire  [2:0] format;
    output reg  [31:0] rgba;
    
    // Constant declarations
    localparam  rgb565 = 3'b0;
    localparam  rgba5551 = 3'b1;
    localparam  rgba4444 = 3'b10;
    localparam  rgb888 = 3'b11;
    
    // Local signals
    reg  [4:0] c5r;
    reg  [4:0] c5g;
    reg  [5:0] c6g;
    reg  [7:0] r;
    reg  [7:0] g;
    reg  [7:0] b;
    reg  [7:0] a;
    
    // Update code
    always @(*) begin
        c5r = word[(32'hb)+:(5)];
        c5g = word[(32'h6)+:(5)];
        c6g = word[(32'h5)+:(6)];
        r = word[(32'h18)+:(8)];
        g = word[(32'h10)+:(8)];
        b = word[(32'h8)+:(8)];
        a = word[(32'h0)+:(8)];
        if (format == rgb565) begin
            r = (((c5r) & 8'hff) << 32'h3) | ((c5r[(32'h2)+:(3)]) & 8'hff);
            g = (((c6g) & 8'hff) << 32'h2) | ((c6g[(32'h4)+:(2)]) & 8'hff);
            b = (((word[(32'h0)+:(5)]) & 8'hff) << 32'h3) | ((word[(32'h2)+:(3)]) & 8'hff);
            a = 32'hff;
        end
        if (format == rgba5551) begin
            r = (((c5r) & 8'hff) << 32'h3) | ((c5r[(32'h2)+:(3)]) & 8'hff);
            g = (((c5g) & 8'hff) << 32'h3) | ((c5g[(32'h2)+:(3)]) & 8'hff);
            b = (((word[(32'h1)+:(5)]) & 8'hff) << 32'h3) | ((word[(32'h3)+:(3)]) & 8'hff);
            a = 32'h0;
            if (word[32'h0]) begin
                a = 32'hff;
            end
        end
        if (format == rgba4444) begin
            r = (((word[(32'hc)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'hc)+:(4)]) & 8'hff);
            g = (((word[(32'h8)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'h8)+:(4)]) & 8'hff);
            b = (((word[(32'h4)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'h4)+:(4)]) & 8'hff);
            a = (((word[(32'h0)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'h0)+:(4)]) & 8'hff);
        end
        if (format == rgb888) begin
            r = word[(32'h10)+:(8)];
            g = word[(32'h8)+:(8)];
            b = word[(32'h0)+:(8)];
            a = 32'hff;
        end
        rgba = (((r) & 32'hffffffff) << 32'h18) | (((g) & 32'hffffffff) << 32'h10) | (((b) & 32'hffffffff) << 32'h8) | ((a) & 32'hffffffff);
    end
    
endmodule // texture_path$unit$filter$decode$3


module texture_path$unit$filter$decode$4(word,format,rgba);
    
    // Module arguments
    input wire  [31:0] word;
    input wire  [2:0] format;
    output reg  [31:0] rgba;
    
    // Constant declarations
    localparam  rgb565 = 3'b0;
    localparam  rgba5551 = 3'b1;
    localparam  rgba4444 = 3'b10;
    localparam  rgb888 = 3'b11;
    
    // Local signals
    reg  [4:0] c5r;
    reg  [4:0] c5g;
    reg  [5:0] c6g;
    reg  [7:0] r;
    reg  [7:0] g;
    reg  [7:0] b;
    reg  [7:0] a;
    
    // Update code
    always @(*) begin
        c5r = word[(32'hb)+:(5)];
        c5g = word[(32'h6)+:(5)];
        c6g = word[(32'h5)+:(6)];
        r = word[(32'h18)+:(8)];
        g = word[(32'h10)+:(8)];
        b = word[(32'h8)+:(8)];
        a = word[(32'h0)+:(8)];
        if (format == rgb565) begin
            r = (((c5r) & 8'hff) << 32'h3) | ((c5r[(32'h2)+:(3)]) & 8'hff);
            g = (((c6g) & 8'hff) << 32'h2) | ((c6g[(32'h4)+:(2)]) & 8'hff);
            b = (((word[(32'h0)+:(5)]) & 8'hff) << 32'h3) | ((word[(32'h2)+:(3)]) & 8'hff);
            a = 32'hff;
        end
        if (format == rgba5551) begin
            r = (((c5r) & 8'hff) << 32'h3) | ((c5r[(32'h2)+:(3)]) & 8'hff);
            g = (((c5g) & 8'hff) << 32'h3) | ((c5g[(32'h2)+:(3)]) & 8'hff);
            b = (((word[(32'h1)+:(5)]) & 8'hff) << 32'h3) | ((word[(32'h3)+:(3)]) & 8'hff);
            a = 32'h0;
            if (word[32'h0]) begin
                a = 32'hff;
            end
        end
        if (format == rgba4444) begin
            r = (((word[(32'hc)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'hc)+:(4)]) & 8'hff);
            g = (((word[(32'h8)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'h8)+:(4)]) & 8'hff);
            b = (((word[(32'h4)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'h4)+:(4)]) & 8'hff);
            a = (((word[(32'h0)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'h0)+:(4)]) & 8'hff);
        end
        if (format == rgb888) begin
            r = word[(32'h10)+:(8)];
            g = word[(32'h8)+:(8)];
            b = word[(32'h0)+:(8)];
            a = 32'hff;
        end
        rgba = (((r) & 32'hffffffff) << 32'h18) | (((g) & 32'hffffffff) << 32'h10) | (((b) & 32'hffffffff) << 32'h8) | ((a) & 32'hffffffff);
    end
    
endmodule // texture_path$unit$filter$decode$4


module texture_path$unit$filter$decode$5(word,format,rgba);
    
    // Module arguments
    input wire  [31:0] word;
    input wire  [2:0] format;
    output reg  [31:0] rgba;
    
    // Constant declarations
    localparam  rgb565 = 3'b0;
    localparam  rgba5551 = 3'b1;
    localparam  rgba4444 = 3'b10;
    localparam  rgb888 = 3'b11;
    
    // Local signals
    reg  [4:0] c5r;
    reg  [4:0] c5g;
    reg  [5:0] c6g;
    reg  [7:0] r;
    reg  [7:0] g;
    reg  [7:0] b;
    reg  [7:0] a;
    
    // Update code
    always @(*) begin
        c5r = word[(32'hb)+:(5)];
        c5g = word[(32'h6)+:(5)];
        c6g = word[(32'h5)+:(6)];
        r = word[(32'h18)+:(8)];
        g = word[(32'h10)+:(8)];
        b = word[(32'h8)+:(8)];
        a = word[(32'h0)+:(8)];
        if (format == rgb565) begin
            r = (((c5r) & 8'hff) << 32'h3) | ((c5r[(32'h2)+:(3)]) & 8'hff);
            g = (((c6g) & 8'hff) << 32'h2) | ((c6g[(32'h4)+:(2)]) & 8'hff);
            b = (((word[(32'h0)+:(5)]) & 8'hff) << 32'h3) | ((word[(32'h2)+:(3)]) & 8'hff);
            a = 32'hff;
        end
        if (format == rgba5551) begin
            r = (((c5r) & 8'hff) << 32'h3) | ((c5r[(32'h2)+:(3)]) & 8'hff);
            g = (((c5g) & 8'hff) << 32'h3) | ((c5g[(32'h2)+:(3)]) & 8'hff);
            b = (((word[(32'h1)+:(5)]) & 8'hff) << 32'h3) | ((word[(32'h3)+:(3)]) & 8'hff);
            a = 32'h0;
            if (word[32'h0]) begin
                a = 32'hff;
            end
        end
        if (format == rgba4444) begin
            r = (((word[(32'hc)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'hc)+:(4)]) & 8'hff);
            g = (((word[(32'h8)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'h8)+:(4)]) & 8'hff);
            b = (((word[(32'h4)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'h4)+:(4)]) & 8'hff);
            a = (((word[(32'h0)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'h0)+:(4)]) & 8'hff);
        end
        if (format == rgb888) begin
            r = word[(32'h10)+:(8)];
            g = word[(32'h8)+:(8)];
            b = word[(32'h0)+:(8)];
            a = 32'hff;
        end
        rgba = (((r) & 32'hffffffff) << 32'h18) | (((g) & 32'hffffffff) << 32'h10) | (((b) & 32'hffffffff) << 32'h8) | ((a) & 32'hffffffff);
    end
    
endmodule // texture_path$unit$filter$decode$5


module texture_path$unit$filter$decode$6(word,format,rgba);
    
    // Module arguments
    input wire  [31:0] word;
    input wire  [2:0] format;
    output reg  [31:0] rgba;
    
    // Constant declarations
    localparam  rgb565 = 3'b0;
    localparam  rgba5551 = 3'b1;
    localparam  rgba4444 = 3'b10;
    localparam  rgb888 = 3'b11;
    
    // Local signals
    reg  [4:0] c5r;
    reg  [4:0] c5g;
    reg  [5:0] c6g;
    reg  [7:0] r;
    reg  [7:0] g;
    reg  [7:0] b;
    reg  [7:0] a;
    
    // Update code
    always @(*) begin
        c5r = word[(32'hb)+:(5)];
        c5g = word[(32'h6)+:(5)];
        c6g = word[(32'h5)+:(6)];
        r = word[(32'h18)+:(8)];
        g = word[(32'h10)+:(8)];
        b = word[(32'h8)+:(8)];
        a = word[(32'h0)+:(8)];
        if (format == rgb565) begin
            r = (((c5r) & 8'hff) << 32'h3) | ((c5r[(32'h2)+:(3)]) & 8'hff);
            g = (((c6g) & 8'hff) << 32'h2) | ((c6g[(32'h4)+:(2)]) & 8'hff);
            b = (((word[(32'h0)+:(5)]) & 8'hff) << 32'h3) | ((word[(32'h2)+:(3)]) & 8'hff);
            a = 32'hff;
        end
        if (format == rgba5551) begin
            r = (((c5r) & 8'hff) << 32'h3) | ((c5r[(32'h2)+:(3)]) & 8'hff);
            g = (((c5g) & 8'hff) << 32'h3) | ((c5g[(32'h2)+:(3)]) & 8'hff);
            b = (((word[(32'h1)+:(5)]) & 8'hff) << 32'h3) | ((word[(32'h3)+:(3)]) & 8'hff);
            a = 32'h0;
            if (word[32'h0]) begin
                a = 32'hff;
            end
        end
        if (format == rgba4444) begin
            r = (((word[(32'hc)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'hc)+:(4)]) & 8'hff);
            g = (((word[(32'h8)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'h8)+:(4)]) & 8'hff);
            b = (((word[(32'h4)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'h4)+:(4)]) & 8'hff);
            a = (((word[(32'h0)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'h0)+:(4)]) & 8'hff);
        end
        if (format == rgb888) begin
            r = word[(32'h10)+:(8)];
            g = word[(32'h8)+:(8)];
            b = word[(32'h0)+:(8)];
            a = 32'hff;
        end
        rgba = (((r) & 32'hffffffff) << 32'h18) | (((g) & 32'hffffffff) << 32'h10) | (((b) & 32'hffffffff) << 32'h8) | ((a) & 32'hffffffff);
    end
    
endmodule // texture_path$unit$filter$decode$6


module texture_path$unit$filter$decode$7(word,format,rgba);
    
    // Module arguments
    input wire  [31:0] word;
    input wire  [2:0] format;
    output reg  [31:0] rgba;
    
    // Constant declarations
    localparam  rgb565 = 3'b0;
    localparam  rgba5551 = 3'b1;
    localparam  rgba4444 = 3'b10;
    localparam  rgb888 = 3'b11;
    
    // Local signals
    reg  [4:0] c5r;
    reg  [4:0] c5g;
    reg  [5:0] c6g;
    reg  [7:0] r;
    reg  [7:0] g;
    reg  [7:0] b;
    reg  [7:0] a;
    
    // Update code
    always @(*) begin
        c5r = word[(32'hb)+:(5)];
        c5g = word[(32'h6)+:(5)];
        c6g = word[(32'h5)+:(6)];
        r = word[(32'h18)+:(8)];
        g = word[(32'h10)+:(8)];
        b = word[(32'h8)+:(8)];
        a = word[(32'h0)+:(8)];
        if (format == rgb565) begin
            r = (((c5r) & 8'hff) << 32'h3) | ((c5r[(32'h2)+:(3)]) & 8'hff);
            g = (((c6g) & 8'hff) << 32'h2) | ((c6g[(32'h4)+:(2)]) & 8'hff);
            b = (((word[(32'h0)+:(5)]) & 8'hff) << 32'h3) | ((word[(32'h2)+:(3)]) & 8'hff);
            a = 32'hff;
        end
        if (format == rgba5551) begin
            r = (((c5r) & 8'hff) << 32'h3) | ((c5r[(32'h2)+:(3)]) & 8'hff);
            g = (((c5g) & 8'hff) << 32'h3) | ((c5g[(32'h2)+:(3)]) & 8'hff);
            b = (((word[(32'h1)+:(5)]) & 8'hff) << 32'h3) | ((word[(32'h3)+:(3)]) & 8'hff);
            a = 32'h0;
            if (word[32'h0]) begin
                a = 32'hff;
            end
        end
        if (format == rgba4444) begin
            r = (((word[(32'hc)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'hc)+:(4)]) & 8'hff);
            g = (((word[(32'h8)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'h8)+:(4)]) & 8'hff);
            b = (((word[(32'h4)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'h4)+:(4)]) & 8'hff);
            a = (((word[(32'h0)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'h0)+:(4)]) & 8'hff);
        end
        if (format == rgb888) begin
            r = word[(32'h10)+:(8)];
            g = word[(32'h8)+:(8)];
            b = word[(32'h0)+:(8)];
            a = 32'hff;
        end
        rgba = (((r) & 32'hffffffff) << 32'h18) | (((g) & 32'hffffffff) << 32'h10) | (((b) & 32'hffffffff) << 32'h8) | ((a) & 32'hffffffff);
    end
    
endmodule // texture_path$unit$filter$decode$7


module texture_path$unit$filter$environment$0(cf,cs,a_s,mode,out);
    
    // Module arguments
    input wire  [7:0] cf;
    input wire  [7:0] cs;
    input wire  [7:0] a_s;
    input wire  [2:0] mode;
    output reg  [7:0] out;
    
    // Constant declarations
    localparam  modulate = 3'b1;
    localparam  decal = 3'b10;
    localparam  blend = 3'b11;
    localparam  add = 3'b100;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [8:0] mul$b;
    wire  [16:0] mul$p;
    
    // Local signals
    reg  [16:0] prod;
    reg  [16:0] biased;
    reg  [7:0] rounded;
    reg  [8:0] sum;
    reg  [7:0] inv_cs;
    reg  [16:0] base;
    
    // Sub module instances
    texture_path$unit$filter$environment$0$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        base = 32'h0;
        mul$a = ((cf) & 9'h1ff);
        mul$b = ((cs) & 9'h1ff);
        inv_cs = ~cs;
        if (mode == blend) begin
            mul$b = ((inv_cs) & 9'h1ff);
        end
        if (mode == decal) begin
            base = (((cf) & 17'h1ffff) << 32'h8) - ((cf) & 17'h1ffff);
            mul$a = ((cs) & 9'h1ff) - ((cf) & 9'h1ff);
            mul$b = ((a_s) & 9'h1ff);
        end
        prod = base + mul$p;
        biased = prod + 32'h80;
        rounded = (((biased + (biased >> 32'h8)) >> 32'h8) & 8'hff);
        sum = ((cf) & 9'h1ff) + ((cs) & 9'h1ff);
        out = cs;
        if ((mode == modulate) | (mode == decal) | (mode == blend)) begin
            out = rounded;
        end
        if (mode == add) begin
            out = sum[(32'h0)+:(8)];
            if (sum[32'h8]) begin
                out = 32'hff;
            end
        end
    end
    
endmodule // texture_path$unit$filter$environment$0


module texture_path$unit$filter$environment$0$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [8:0] b;
    output reg  [16:0] p;
    
    // Update code (custom)
    // p = low 17 bits of a * b, both signed: a signed 17-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_path$unit$filter$environment$0$mul


module texture_path$unit$filter$environment$1(cf,cs,a_s,mode,out);
    
    // Module arguments
    input wire  [7:0] cf;
    input wire  [7:0] cs;
    input wire  [7:0] a_s;
    input wire  [2:0] mode;
    output reg  [7:0] out;
    
    // Constant declarations
    localparam  modulate = 3'b1;
    localparam  decal = 3'b10;
    localparam  blend = 3'b11;
    localparam  add = 3'b100;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [8:0] mul$b;
    wire  [16:0] mul$p;
    
    // Local signals
    reg  [16:0] prod;
    reg  [16:0] biased;
    reg  [7:0] rounded;
    reg  [8:0] sum;
    reg  [7:0] inv_cs;
    reg  [16:0] base;
    
    // Sub module instances
    texture_path$unit$filter$environment$1$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        base = 32'h0;
        mul$a = ((cf) & 9'h1ff);
        mul$b = ((cs) & 9'h1ff);
        inv_cs = ~cs;
        if (mode == blend) begin
            mul$b = ((inv_cs) & 9'h1ff);
        end
        if (mode == decal) begin
            base = (((cf) & 17'h1ffff) << 32'h8) - ((cf) & 17'h1ffff);
            mul$a = ((cs) & 9'h1ff) - ((cf) & 9'h1ff);
            mul$b = ((a_s) & 9'h1ff);
        end
        prod = base + mul$p;
        biased = prod + 32'h80;
        rounded = (((biased + (biased >> 32'h8)) >> 32'h8) & 8'hff);
        sum = ((cf) & 9'h1ff) + ((cs) & 9'h1ff);
        out = cs;
        if ((mode == modulate) | (mode == decal) | (mode == blend)) begin
            out = rounded;
        end
        if (mode == add) begin
            out = sum[(32'h0)+:(8)];
            if (sum[32'h8]) begin
                out = 32'hff;
            end
        end
    end
    
endmodule // texture_path$unit$filter$environment$1


module texture_path$unit$filter$environment$1$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [8:0] b;
    output reg  [16:0] p;
    
    // Update code (custom)
    // p = low 17 bits of a * b, both signed: a signed 17-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_path$unit$filter$environment$1$mul


module texture_path$unit$filter$environment$2(cf,cs,a_s,mode,out);
    
    // Module arguments
    input wire  [7:0] cf;
    input wire  [7:0] cs;
    input wire  [7:0] a_s;
    input wire  [2:0] mode;
    output reg  [7:0] out;
    
    // Constant declarations
    localparam  modulate = 3'b1;
    localparam  decal = 3'b10;
    localparam  blend = 3'b11;
    localparam  add = 3'b100;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [8:0] mul$b;
    wire  [16:0] mul$p;
    
    // Local signals
    reg  [16:0] prod;
    reg  [16:0] biased;
    reg  [7:0] rounded;
    reg  [8:0] sum;
    reg  [7:0] inv_cs;
    reg  [16:0] base;
    
    // Sub module instances
    texture_path$unit$filter$environment$2$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        base = 32'h0;
        mul$a = ((cf) & 9'h1ff);
        mul$b = ((cs) & 9'h1ff);
        inv_cs = ~cs;
        if (mode == blend) begin
            mul$b = ((inv_cs) & 9'h1ff);
        end
        if (mode == decal) begin
            base = (((cf) & 17'h1ffff) << 32'h8) - ((cf) & 17'h1ffff);
            mul$a = ((cs) & 9'h1ff) - ((cf) & 9'h1ff);
            mul$b = ((a_s) & 9'h1ff);
        end
        prod = base + mul$p;
        biased = prod + 32'h80;
        rounded = (((biased + (biased >> 32'h8)) >> 32'h8) & 8'hff);
        sum = ((cf) & 9'h1ff) + ((cs) & 9'h1ff);
        out = cs;
        if ((mode == modulate) | (mode == decal) | (mode == blend)) begin
            out = rounded;
        end
        if (mode == add) begin
            out = sum[(32'h0)+:(8)];
            if (sum[32'h8]) begin
                out = 32'hff;
            end
        end
    end
    
endmodule // texture_path$unit$filter$environment$2


module texture_path$unit$filter$environment$2$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [8:0] b;
    output reg  [16:0] p;
    
    // Update code (custom)
    // p = low 17 bits of a * b, both signed: a signed 17-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_path$unit$filter$environment$2$mul


module texture_path$unit$filter$level$0(clock,en,t0,t1,t2,t3,a,b,c);
    
    // Module arguments
    input wire  clock;
    input wire  en;
    input wire  [31:0] t0;
    input wire  [31:0] t1;
    input wire  [31:0] t2;
    input wire  [31:0] t3;
    input wire  [8:0] a;
    input wire  [8:0] b;
    output reg  [31:0] c;
    
    // Stub signals
    reg  [7:0] h$0$x0;
    reg  [7:0] h$0$x1;
    reg  [8:0] h$0$w;
    wire  [15:0] h$0$y;
    reg  [7:0] h$1$x0;
    reg  [7:0] h$1$x1;
    reg  [8:0] h$1$w;
    wire  [15:0] h$1$y;
    reg  [7:0] h$2$x0;
    reg  [7:0] h$2$x1;
    reg  [8:0] h$2$w;
    wire  [15:0] h$2$y;
    reg  [7:0] h$3$x0;
    reg  [7:0] h$3$x1;
    reg  [8:0] h$3$w;
    wire  [15:0] h$3$y;
    reg  [7:0] h$4$x0;
    reg  [7:0] h$4$x1;
    reg  [8:0] h$4$w;
    wire  [15:0] h$4$y;
    reg  [7:0] h$5$x0;
    reg  [7:0] h$5$x1;
    reg  [8:0] h$5$w;
    wire  [15:0] h$5$y;
    reg  [7:0] h$6$x0;
    reg  [7:0] h$6$x1;
    reg  [8:0] h$6$w;
    wire  [15:0] h$6$y;
    reg  [7:0] h$7$x0;
    reg  [7:0] h$7$x1;
    reg  [8:0] h$7$w;
    wire  [15:0] h$7$y;
    reg  [15:0] h_r$0$d;
    wire  [15:0] h_r$0$q;
    reg  h_r$0$clock;
    reg  [15:0] h_r$1$d;
    wire  [15:0] h_r$1$q;
    reg  h_r$1$clock;
    reg  [15:0] h_r$2$d;
    wire  [15:0] h_r$2$q;
    reg  h_r$2$clock;
    reg  [15:0] h_r$3$d;
    wire  [15:0] h_r$3$q;
    reg  h_r$3$clock;
    reg  [15:0] h_r$4$d;
    wire  [15:0] h_r$4$q;
    reg  h_r$4$clock;
    reg  [15:0] h_r$5$d;
    wire  [15:0] h_r$5$q;
    reg  h_r$5$clock;
    reg  [15:0] h_r$6$d;
    wire  [15:0] h_r$6$q;
    reg  h_r$6$clock;
    reg  [15:0] h_r$7$d;
    wire  [15:0] h_r$7$q;
    reg  h_r$7$clock;
    reg  [8:0] b_r$d;
    wire  [8:0] b_r$q;
    reg  b_r$clock;
    reg  [15:0] v$0$x0;
    reg  [15:0] v$0$x1;
    reg  [8:0] v$0$w;
    wire  [23:0] v$0$y;
    reg  [15:0] v$1$x0;
    reg  [15:0] v$1$x1;
    reg  [8:0] v$1$w;
    wire  [23:0] v$1$y;
    reg  [15:0] v$2$x0;
    reg  [15:0] v$2$x1;
    reg  [8:0] v$2$w;
    wire  [23:0] v$2$y;
    reg  [15:0] v$3$x0;
    reg  [15:0] v$3$x1;
    reg  [8:0] v$3$w;
    wire  [23:0] v$3$y;
    reg  [23:0] round$0$x;
    wire  [7:0] round$0$y;
    reg  [23:0] round$1$x;
    wire  [7:0] round$1$y;
    reg  [23:0] round$2$x;
    wire  [7:0] round$2$y;
    reg  [23:0] round$3$x;
    wire  [7:0] round$3$y;
    reg  [7:0] c_r$0$d;
    wire  [7:0] c_r$0$q;
    reg  c_r$0$clock;
    reg  [7:0] c_r$1$d;
    wire  [7:0] c_r$1$q;
    reg  c_r$1$clock;
    reg  [7:0] c_r$2$d;
    wire  [7:0] c_r$2$q;
    reg  c_r$2$clock;
    reg  [7:0] c_r$3$d;
    wire  [7:0] c_r$3$q;
    reg  c_r$3$clock;
    
    // Sub module instances
    texture_path$unit$filter$level$0$h$0 h$0(
        .x0(h$0$x0),
        .x1(h$0$x1),
        .w(h$0$w),
        .y(h$0$y)
    );
    texture_path$unit$filter$level$0$h$1 h$1(
        .x0(h$1$x0),
        .x1(h$1$x1),
        .w(h$1$w),
        .y(h$1$y)
    );
    texture_path$unit$filter$level$0$h$2 h$2(
        .x0(h$2$x0),
        .x1(h$2$x1),
        .w(h$2$w),
        .y(h$2$y)
    );
    texture_path$unit$filter$level$0$h$3 h$3(
        .x0(h$3$x0),
        .x1(h$3$x1),
        .w(h$3$w),
        .y(h$3$y)
    );
    texture_path$unit$filter$level$0$h$4 h$4(
        .x0(h$4$x0),
        .x1(h$4$x1),
        .w(h$4$w),
        .y(h$4$y)
    );
    texture_path$unit$filter$level$0$h$5 h$5(
        .x0(h$5$x0),
        .x1(h$5$x1),
        .w(h$5$w),
        .y(h$5$y)
    );
    texture_path$unit$filter$level$0$h$6 h$6(
        .x0(h$6$x0),
        .x1(h$6$x1),
        .w(h$6$w),
        .y(h$6$y)
    );
    texture_path$unit$filter$level$0$h$7 h$7(
        .x0(h$7$x0),
        .x1(h$7$x1),
        .w(h$7$w),
        .y(h$7$y)
    );
    texture_path$unit$filter$level$0$h_r$0 h_r$0(
        .d(h_r$0$d),
        .q(h_r$0$q),
        .clock(h_r$0$clock)
    );
    texture_path$unit$filter$level$0$h_r$1 h_r$1(
        .d(h_r$1$d),
        .q(h_r$1$q),
        .clock(h_r$1$clock)
    );
    texture_path$unit$filter$level$0$h_r$2 h_r$2(
        .d(h_r$2$d),
        .q(h_r$2$q),
        .clock(h_r$2$clock)
    );
    texture_path$unit$filter$level$0$h_r$3 h_r$3(
        .d(h_r$3$d),
        .q(h_r$3$q),
        .clock(h_r$3$clock)
    );
    texture_path$unit$filter$level$0$h_r$4 h_r$4(
        .d(h_r$4$d),
        .q(h_r$4$q),
        .clock(h_r$4$clock)
    );
    texture_path$unit$filter$level$0$h_r$5 h_r$5(
        .d(h_r$5$d),
        .q(h_r$5$q),
        .clock(h_r$5$clock)
    );
    texture_path$unit$filter$level$0$h_r$6 h_r$6(
        .d(h_r$6$d),
        .q(h_r$6$q),
        .clock(h_r$6$clock)
    );
    texture_path$unit$filter$level$0$h_r$7 h_r$7(
        .d(h_r$7$d),
        .q(h_r$7$q),
        .clock(h_r$7$clock)
    );
    texture_path$unit$filter$level$0$b_r b_r(
        .d(b_r$d),
        .q(b_r$q),
        .clock(b_r$clock)
    );
    texture_path$unit$filter$level$0$v$0 v$0(
        .x0(v$0$x0),
        .x1(v$0$x1),
        .w(v$0$w),
        .y(v$0$y)
    );
    texture_path$unit$filter$level$0$v$1 v$1(
        .x0(v$1$x0),
        .x1(v$1$x1),
        .w(v$1$w),
        .y(v$1$y)
    );
    texture_path$unit$filter$level$0$v$2 v$2(
        .x0(v$2$x0),
        .x1(v$2$x1),
        .w(v$2$w),
        .y(v$2$y)
    );
    texture_path$unit$filter$level$0$v$3 v$3(
        .x0(v$3$x0),
        .x1(v$3$x1),
        .w(v$3$w),
        .y(v$3$y)
    );
    texture_path$unit$filter$level$0$round$0 round$0(
        .x(round$0$x),
        .y(round$0$y)
    );
    texture_path$unit$filter$level$0$round$1 round$1(
        .x(round$1$x),
        .y(round$1$y)
    );
    texture_path$unit$filter$level$0$round$2 round$2(
        .x(round$2$x),
        .y(round$2$y)
    );
    texture_path$unit$filter$level$0$round$3 round$3(
        .x(round$3$x),
        .y(round$3$y)
    );
    texture_path$unit$filter$level$0$c_r$0 c_r$0(
        .d(c_r$0$d),
        .q(c_r$0$q),
        .clock(c_r$0$clock)
    );
    texture_path$unit$filter$level$0$c_r$1 c_r$1(
        .d(c_r$1$d),
        .q(c_r$1$q),
        .clock(c_r$1$clock)
    );
    texture_path$unit$filter$level$0$c_r$2 c_r$2(
        .d(c_r$2$d),
        .q(c_r$2$q),
        .clock(c_r$2$clock)
    );
    texture_path$unit$filter$level$0$c_r$3 c_r$3(
        .d(c_r$3$d),
        .q(c_r$3$q),
        .clock(c_r$3$clock)
    );
    
    // Update code
    always @(*) begin
        b_r$clock = clock;
        b_r$d = b_r$q;
        h_r$0$clock = clock;
        h_r$0$d = h_r$0$q;
        h_r$1$clock = clock;
        h_r$1$d = h_r$1$q;
        h_r$2$clock = clock;
        h_r$2$d = h_r$2$q;
        h_r$3$clock = clock;
        h_r$3$d = h_r$3$q;
        h_r$4$clock = clock;
        h_r$4$d = h_r$4$q;
        h_r$5$clock = clock;
        h_r$5$d = h_r$5$q;
        h_r$6$clock = clock;
        h_r$6$d = h_r$6$q;
        h_r$7$clock = clock;
        h_r$7$d = h_r$7$q;
        c_r$0$clock = clock;
        c_r$0$d = c_r$0$q;
        c_r$1$clock = clock;
        c_r$1$d = c_r$1$q;
        c_r$2$clock = clock;
        c_r$2$d = c_r$2$q;
        c_r$3$clock = clock;
        c_r$3$d = c_r$3$q;
        h$0$x0 = t0[(0 * 32'h8)+:(8)];
        h$0$x1 = t1[(0 * 32'h8)+:(8)];
        h$0$w = a;
        h$4$x0 = t2[(0 * 32'h8)+:(8)];
        h$4$x1 = t3[(0 * 32'h8)+:(8)];
        h$4$w = a;
        v$0$x0 = h_r$0$q;
        v$0$x1 = h_r$4$q;
        v$0$w = b_r$q;
        round$0$x = v$0$y;
        h$1$x0 = t0[(1 * 32'h8)+:(8)];
        h$1$x1 = t1[(1 * 32'h8)+:(8)];
        h$1$w = a;
        h$5$x0 = t2[(1 * 32'h8)+:(8)];
        h$5$x1 = t3[(1 * 32'h8)+:(8)];
        h$5$w = a;
        v$1$x0 = h_r$1$q;
        v$1$x1 = h_r$5$q;
        v$1$w = b_r$q;
        round$1$x = v$1$y;
        h$2$x0 = t0[(2 * 32'h8)+:(8)];
        h$2$x1 = t1[(2 * 32'h8)+:(8)];
        h$2$w = a;
        h$6$x0 = t2[(2 * 32'h8)+:(8)];
        h$6$x1 = t3[(2 * 32'h8)+:(8)];
        h$6$w = a;
        v$2$x0 = h_r$2$q;
        v$2$x1 = h_r$6$q;
        v$2$w = b_r$q;
        round$2$x = v$2$y;
        h$3$x0 = t0[(3 * 32'h8)+:(8)];
        h$3$x1 = t1[(3 * 32'h8)+:(8)];
        h$3$w = a;
        h$7$x0 = t2[(3 * 32'h8)+:(8)];
        h$7$x1 = t3[(3 * 32'h8)+:(8)];
        h$7$w = a;
        v$3$x0 = h_r$3$q;
        v$3$x1 = h_r$7$q;
        v$3$w = b_r$q;
        round$3$x = v$3$y;
        if (en) begin
            h_r$0$d = h$0$y;
            h_r$1$d = h$1$y;
            h_r$2$d = h$2$y;
            h_r$3$d = h$3$y;
            h_r$4$d = h$4$y;
            h_r$5$d = h$5$y;
            h_r$6$d = h$6$y;
            h_r$7$d = h$7$y;
            b_r$d = b;
            c_r$0$d = round$0$y;
            c_r$1$d = round$1$y;
            c_r$2$d = round$2$y;
            c_r$3$d = round$3$y;
        end
        c = (((c_r$3$q) & 32'hffffffff) << 32'h18) | (((c_r$2$q) & 32'hffffffff) << 32'h10) | (((c_r$1$q) & 32'hffffffff) << 32'h8) | ((c_r$0$q) & 32'hffffffff);
    end
    
endmodule // texture_path$unit$filter$level$0


module texture_path$unit$filter$level$0$b_r(d,q,clock);
    
    // Module arguments
    input wire  [8:0] d;
    output reg  [8:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 9'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$level$0$b_r


module texture_path$unit$filter$level$0$c_r$0(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$level$0$c_r$0


module texture_path$unit$filter$level$0$c_r$1(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$level$0$c_r$1


module texture_path$unit$filter$level$0$c_r$2(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$level$0$c_r$2


module texture_path$unit$filter$level$0$c_r$3(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$level$0$c_r$3


module texture_path$unit$filter$level$0$h$0(x0,x1,w,y);
    
    // Module arguments
    input wire  [7:0] x0;
    input wire  [7:0] x1;
    input wire  [8:0] w;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  s = 8'h8;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [9:0] mul$b;
    wire  [16:0] mul$p;
    
    // Sub module instances
    texture_path$unit$filter$level$0$h$0$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 9'h1ff) - ((x0) & 9'h1ff);
        mul$b = ((w) & 10'h3ff);
        y = (((((x0) & 17'h1ffff) << s) + mul$p) & 16'hffff);
    end
    
endmodule // texture_path$unit$filter$level$0$h$0


module texture_path$unit$filter$level$0$h$0$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [9:0] b;
    output reg  [16:0] p;
    
    // Update code (custom)
    // p = low 17 bits of a * b, both signed: a signed 17-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_path$unit$filter$level$0$h$0$mul


module texture_path$unit$filter$level$0$h$1(x0,x1,w,y);
    
    // Module arguments
    input wire  [7:0] x0;
    input wire  [7:0] x1;
    input wire  [8:0] w;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  s = 8'h8;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [9:0] mul$b;
    wire  [16:0] mul$p;
    
    // Sub module instances
    texture_path$unit$filter$level$0$h$1$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 9'h1ff) - ((x0) & 9'h1ff);
        mul$b = ((w) & 10'h3ff);
        y = (((((x0) & 17'h1ffff) << s) + mul$p) & 16'hffff);
    end
    
endmodule // texture_path$unit$filter$level$0$h$1


module texture_path$unit$filter$level$0$h$1$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [9:0] b;
    output reg  [16:0] p;
    
    // Update code (custom)
    // p = low 17 bits of a * b, both signed: a signed 17-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_path$unit$filter$level$0$h$1$mul


module texture_path$unit$filter$level$0$h$2(x0,x1,w,y);
    
    // Module arguments
    input wire  [7:0] x0;
    input wire  [7:0] x1;
    input wire  [8:0] w;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  s = 8'h8;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [9:0] mul$b;
    wire  [16:0] mul$p;
    
    // Sub module instances
    texture_path$unit$filter$level$0$h$2$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 9'h1ff) - ((x0) & 9'h1ff);
        mul$b = ((w) & 10'h3ff);
        y = (((((x0) & 17'h1ffff) << s) + mul$p) & 16'hffff);
    end
    
endmodule // texture_path$unit$filter$level$0$h$2


module texture_path$unit$filter$level$0$h$2$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [9:0] b;
    output reg  [16:0] p;
    
    // Update code (custom)
    // p = low 17 bits of a * b, both signed: a signed 17-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_path$unit$filter$level$0$h$2$mul


module texture_path$unit$filter$level$0$h$3(x0,x1,w,y);
    
    // Module arguments
    input wire  [7:0] x0;
    input wire  [7:0] x1;
    input wire  [8:0] w;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  s = 8'h8;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [9:0] mul$b;
    wire  [16:0] mul$p;
    
    // Sub module instances
    texture_path$unit$filter$level$0$h$3$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 9'h1ff) - ((x0) & 9'h1ff);
        mul$b = ((w) & 10'h3ff);
        y = (((((x0) & 17'h1ffff) << s) + mul$p) & 16'hffff);
    end
    
endmodule // texture_path$unit$filter$level$0$h$3


module texture_path$unit$filter$level$0$h$3$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [9:0] b;
    output reg  [16:0] p;
    
    // Update code (custom)
    // p = low 17 bits of a * b, both signed: a signed 17-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_path$unit$filter$level$0$h$3$mul


module texture_path$unit$filter$level$0$h$4(x0,x1,w,y);
    
    // Module arguments
    input wire  [7:0] x0;
    input wire  [7:0] x1;
    input wire  [8:0] w;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  s = 8'h8;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [9:0] mul$b;
    wire  [16:0] mul$p;
    
    // Sub module instances
    texture_path$unit$filter$level$0$h$4$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 9'h1ff) - ((x0) & 9'h1ff);
        mul$b = ((w) & 10'h3ff);
        y = (((((x0) & 17'h1ffff) << s) + mul$p) & 16'hffff);
    end
    
endmodule // texture_path$unit$filter$level$0$h$4


module texture_path$unit$filter$level$0$h$4$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [9:0] b;
    output reg  [16:0] p;
    
    // Update code (custom)
    // p = low 17 bits of a * b, both signed: a signed 17-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_path$unit$filter$level$0$h$4$mul


module texture_path$unit$filter$level$0$h$5(x0,x1,w,y);
    
    // Module arguments
    input wire  [7:0] x0;
    input wire  [7:0] x1;
    input wire  [8:0] w;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  s = 8'h8;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [9:0] mul$b;
    wire  [16:0] mul$p;
    
    // Sub module instances
    texture_path$unit$filter$level$0$h$5$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 9'h1ff) - ((x0) & 9'h1ff);
        mul$b = ((w) & 10'h3ff);
        y = (((((x0) & 17'h1ffff) << s) + mul$p) & 16'hffff);
    end
    
endmodule // texture_path$unit$filter$level$0$h$5


module texture_path$unit$filter$level$0$h$5$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [9:0] b;
    output reg  [16:0] p;
    
    // Update code (custom)
    // p = low 17 bits of a * b, both signed: a signed 17-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_path$unit$filter$level$0$h$5$mul


module texture_path$unit$filter$level$0$h$6(x0,x1,w,y);
    
    // Module arguments
    input wire  [7:0] x0;
    input wire  [7:0] x1;
    input wire  [8:0] w;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  s = 8'h8;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [9:0] mul$b;
    wire  [16:0] mul$p;
    
    // Sub module instances
    texture_path$unit$filter$level$0$h$6$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 9'h1ff) - ((x0) & 9'h1ff);
        mul$b = ((w) & 10'h3ff);
        y = (((((x0) & 17'h1ffff) << s) + mul$p) & 16'hffff);
    end
    
endmodule // texture_path$unit$filter$level$0$h$6


module texture_path$unit$filter$level$0$h$6$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [9:0] b;
    output reg  [16:0] p;
    
    // Update code (custom)
    // p = low 17 bits of a * b, both signed: a signed 17-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_path$unit$filter$level$0$h$6$mul


module texture_path$unit$filter$level$0$h$7(x0,x1,w,y);
    
    // Module arguments
    input wire  [7:0] x0;
    input wire  [7:0] x1;
    input wire  [8:0] w;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  s = 8'h8;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [9:0] mul$b;
    wire  [16:0] mul$p;
    
    // Sub module instances
    texture_path$unit$filter$level$0$h$7$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 9'h1ff) - ((x0) & 9'h1ff);
        mul$b = ((w) & 10'h3ff);
        y = (((((x0) & 17'h1ffff) << s) + mul$p) & 16'hffff);
    end
    
endmodule // texture_path$unit$filter$level$0$h$7


module texture_path$unit$filter$level$0$h$7$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [9:0] b;
    output reg  [16:0] p;
    
    // Update code (custom)
    // p = low 17 bits of a * b, both signed: a signed 17-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_path$unit$filter$level$0$h$7$mul


module texture_path$unit$filter$level$0$h_r$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$level$0$h_r$0


module texture_path$unit$filter$level$0$h_r$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$level$0$h_r$1


module texture_path$unit$filter$level$0$h_r$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$level$0$h_r$2


module texture_path$unit$filter$level$0$h_r$3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$level$0$h_r$3


module texture_path$unit$filter$level$0$h_r$4(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$level$0$h_r$4


module texture_path$unit$filter$level$0$h_r$5(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$level$0$h_r$5


module texture_path$unit$filter$level$0$h_r$6(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$level$0$h_r$6


module texture_path$unit$filter$level$0$h_r$7(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$level$0$h_r$7


module texture_path$unit$filter$level$0$round$0(x,y);
    
    // Module arguments
    input wire  [23:0] x;
    output reg  [7:0] y;
    
    // Constant declarations
    localparam  half = 24'h8000;
    localparam  shift = 8'h10;
    
    // Update code
    always @(*) begin
        y = (((x + half) >> shift) & 8'hff);
    end
    
endmodule // texture_path$unit$filter$level$0$round$0


module texture_path$unit$filter$level$0$round$1(x,y);
    
    // Module arguments
    input wire  [23:0] x;
    output reg  [7:0] y;
    
    // Constant declarations
    localparam  half = 24'h8000;
    localparam  shift = 8'h10;
    
    // Update code
    always @(*) begin
        y = (((x + half) >> shift) & 8'hff);
    end
    
endmodule // texture_path$unit$filter$level$0$round$1


module texture_path$unit$filter$level$0$round$2(x,y);
    
    // Module arguments
    input wire  [23:0] x;
    output reg  [7:0] y;
    
    // Constant declarations
    localparam  half = 24'h8000;
    localparam  shift = 8'h10;
    
    // Update code
    always @(*) begin
        y = (((x + half) >> shift) & 8'hff);
    end
    
endmodule // texture_path$unit$filter$level$0$round$2


module texture_path$unit$filter$level$0$round$3(x,y);
    
    // Module arguments
    input wire  [23:0] x;
    output reg  [7:0] y;
    
    // Constant declarations
    localparam  half = 24'h8000;
    localparam  shift = 8'h10;
    
    // Update code
    always @(*) begin
        y = (((x + half) >> shift) & 8'hff);
    end
    
endmodule // texture_path$unit$filter$level$0$round$3


module texture_path$unit$filter$level$0$v$0(x0,x1,w,y);
    
    // Module arguments
    input wire  [15:0] x0;
    input wire  [15:0] x1;
    input wire  [8:0] w;
    output reg  [23:0] y;
    
    // Constant declarations
    localparam  s = 8'h8;
    
    // Stub signals
    reg  [16:0] mul$a;
    reg  [9:0] mul$b;
    wire  [24:0] mul$p;
    
    // Sub module instances
    texture_path$unit$filter$level$0$v$0$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 17'h1ffff) - ((x0) & 17'h1ffff);
        mul$b = ((w) & 10'h3ff);
        y = (((((x0) & 25'h1ffffff) << s) + mul$p) & 24'hffffff);
    end
    
endmodule // texture_path$unit$filter$level$0$v$0


module texture_path$unit$filter$level$0$v$0$mul(a,b,p);
    
    // Module arguments
    input wire  [16:0] a;
    input wire  [9:0] b;
    output reg  [24:0] p;
    
    // Update code (custom)
    // p = low 25 bits of a * b, both signed: a signed 25-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_path$unit$filter$level$0$v$0$mul


module texture_path$unit$filter$level$0$v$1(x0,x1,w,y);
    
    // Module arguments
    input wire  [15:0] x0;
    input wire  [15:0] x1;
    input wire  [8:0] w;
    output reg  [23:0] y;
    
    // Constant declarations
    localparam  s = 8'h8;
    
    // Stub signals
    reg  [16:0] mul$a;
    reg  [9:0] mul$b;
    wire  [24:0] mul$p;
    
    // Sub module instances
    texture_path$unit$filter$level$0$v$1$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 17'h1ffff) - ((x0) & 17'h1ffff);
        mul$b = ((w) & 10'h3ff);
        y = (((((x0) & 25'h1ffffff) << s) + mul$p) & 24'hffffff);
    end
    
endmodule // texture_path$unit$filter$level$0$v$1


module texture_path$unit$filter$level$0$v$1$mul(a,b,p);
    
    // Module arguments
    input wire  [16:0] a;
    input wire  [9:0] b;
    output reg  [24:0] p;
    
    // Update code (custom)
    // p = low 25 bits of a * b, both signed: a signed 25-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_path$unit$filter$level$0$v$1$mul


module texture_path$unit$filter$level$0$v$2(x0,x1,w,y);
    
    // Module arguments
    input wire  [15:0] x0;
    input wire  [15:0] x1;
    input wire  [8:0] w;
    output reg  [23:0] y;
    
    // Constant declarations
    localparam  s = 8'h8;
    
    // Stub signals
    reg  [16:0] mul$a;
    reg  [9:0] mul$b;
    wire  [24:0] mul$p;
    
    // Sub module instances
    texture_path$unit$filter$level$0$v$2$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 17'h1ffff) - ((x0) & 17'h1ffff);
        mul$b = ((w) & 10'h3ff);
        y = (((((x0) & 25'h1ffffff) << s) + mul$p) & 24'hffffff);
    end
    
endmodule // texture_path$unit$filter$level$0$v$2


module texture_path$unit$filter$level$0$v$2$mul(a,b,p);
    
    // Module arguments
    input wire  [16:0] a;
    input wire  [9:0] b;
    output reg  [24:0] p;
    
    // Update code (custom)
    // p = low 25 bits of a * b, both signed: a signed 25-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_path$unit$filter$level$0$v$2$mul


module texture_path$unit$filter$level$0$v$3(x0,x1,w,y);
    
    // Module arguments
    input wire  [15:0] x0;
    input wire  [15:0] x1;
    input wire  [8:0] w;
    output reg  [23:0] y;
    
    // Constant declarations
    localparam  s = 8'h8;
    
    // Stub signals
    reg  [16:0] mul$a;
    reg  [9:0] mul$b;
    wire  [24:0] mul$p;
    
    // Sub module instances
    texture_path$unit$filter$level$0$v$3$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 17'h1ffff) - ((x0) & 17'h1ffff);
        mul$b = ((w) & 10'h3ff);
        y = (((((x0) & 25'h1ffffff) << s) + mul$p) & 24'hffffff);
    end
    
endmodule // texture_path$unit$filter$level$0$v$3


module texture_path$unit$filter$level$0$v$3$mul(a,b,p);
    
    // Module arguments
    input wire  [16:0] a;
    input wire  [9:0] b;
    output reg  [24:0] p;
    
    // Update code (custom)
    // p = low 25 bits of a * b, both signed: a signed 25-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_path$unit$filter$level$0$v$3$mul


module texture_path$unit$filter$level$1(clock,en,t0,t1,t2,t3,a,b,c);
    
    // Module arguments
    input wire  clock;
    input wire  en;
    input wire  [31:0] t0;
    input wire  [31:0] t1;
    input wire  [31:0] t2;
    input wire  [31:0] t3;
    input wire  [8:0] a;
    input wire  [8:0] b;
    output reg  [31:0] c;
    
    // Stub signals
    reg  [7:0] h$0$x0;
    reg  [7:0] h$0$x1;
    reg  [8:0] h$0$w;
    wire  [15:0] h$0$y;
    reg  [7:0] h$1$x0;
    reg  [7:0] h$1$x1;
    reg  [8:0] h$1$w;
    wire  [15:0] h$1$y;
    reg  [7:0] h$2$x0;
    reg  [7:0] h$2$x1;
    reg  [8:0] h$2$w;
    wire  [15:0] h$2$y;
    reg  [7:0] h$3$x0;
    reg  [7:0] h$3$x1;
    reg  [8:0] h$3$w;
    wire  [15:0] h$3$y;
    reg  [7:0] h$4$x0;
    reg  [7:0] h$4$x1;
    reg  [8:0] h$4$w;
    wire  [15:0] h$4$y;
    reg  [7:0] h$5$x0;
    reg  [7:0] h$5$x1;
    reg  [8:0] h$5$w;
    wire  [15:0] h$5$y;
    reg  [7:0] h$6$x0;
    reg  [7:0] h$6$x1;
    reg  [8:0] h$6$w;
    wire  [15:0] h$6$y;
    reg  [7:0] h$7$x0;
    reg  [7:0] h$7$x1;
    reg  [8:0] h$7$w;
    wire  [15:0] h$7$y;
    reg  [15:0] h_r$0$d;
    wire  [15:0] h_r$0$q;
    reg  h_r$0$clock;
    reg  [15:0] h_r$1$d;
    wire  [15:0] h_r$1$q;
    reg  h_r$1$clock;
    reg  [15:0] h_r$2$d;
    wire  [15:0] h_r$2$q;
    reg  h_r$2$clock;
    reg  [15:0] h_r$3$d;
    wire  [15:0] h_r$3$q;
    reg  h_r$3$clock;
    reg  [15:0] h_r$4$d;
    wire  [15:0] h_r$4$q;
    reg  h_r$4$clock;
    reg  [15:0] h_r$5$d;
    wire  [15:0] h_r$5$q;
    reg  h_r$5$clock;
    reg  [15:0] h_r$6$d;
    wire  [15:0] h_r$6$q;
    reg  h_r$6$clock;
    reg  [15:0] h_r$7$d;
    wire  [15:0] h_r$7$q;
    reg  h_r$7$clock;
    reg  [8:0] b_r$d;
    wire  [8:0] b_r$q;
    reg  b_r$clock;
    reg  [15:0] v$0$x0;
    reg  [15:0] v$0$x1;
    reg  [8:0] v$0$w;
    wire  [23:0] v$0$y;
    reg  [15:0] v$1$x0;
    reg  [15:0] v$1$x1;
    reg  [8:0] v$1$w;
    wire  [23:0] v$1$y;
    reg  [15:0] v$2$x0;
    reg  [15:0] v$2$x1;
    reg  [8:0] v$2$w;
    wire  [23:0] v$2$y;
    reg  [15:0] v$3$x0;
    reg  [15:0] v$3$x1;
    reg  [8:0] v$3$w;
    wire  [23:0] v$3$y;
    reg  [23:0] round$0$x;
    wire  [7:0] round$0$y;
    reg  [23:0] round$1$x;
    wire  [7:0] round$1$y;
    reg  [23:0] round$2$x;
    wire  [7:0] round$2$y;
    reg  [23:0] round$3$x;
    wire  [7:0] round$3$y;
    reg  [7:0] c_r$0$d;
    wire  [7:0] c_r$0$q;
    reg  c_r$0$clock;
    reg  [7:0] c_r$1$d;
    wire  [7:0] c_r$1$q;
    reg  c_r$1$clock;
    reg  [7:0] c_r$2$d;
    wire  [7:0] c_r$2$q;
    reg  c_r$2$clock;
    reg  [7:0] c_r$3$d;
    wire  [7:0] c_r$3$q;
    reg  c_r$3$clock;
    
    // Sub module instances
    texture_path$unit$filter$level$1$h$0 h$0(
        .x0(h$0$x0),
        .x1(h$0$x1),
        .w(h$0$w),
        .y(h$0$y)
    );
    texture_path$unit$filter$level$1$h$1 h$1(
        .x0(h$1$x0),
        .x1(h$1$x1),
        .w(h$1$w),
        .y(h$1$y)
    );
    texture_path$unit$filter$level$1$h$2 h$2(
        .x0(h$2$x0),
        .x1(h$2$x1),
        .w(h$2$w),
        .y(h$2$y)
    );
    texture_path$unit$filter$level$1$h$3 h$3(
        .x0(h$3$x0),
        .x1(h$3$x1),
        .w(h$3$w),
        .y(h$3$y)
    );
    texture_path$unit$filter$level$1$h$4 h$4(
        .x0(h$4$x0),
        .x1(h$4$x1),
        .w(h$4$w),
        .y(h$4$y)
    );
    texture_path$unit$filter$level$1$h$5 h$5(
        .x0(h$5$x0),
        .x1(h$5$x1),
        .w(h$5$w),
        .y(h$5$y)
    );
    texture_path$unit$filter$level$1$h$6 h$6(
        .x0(h$6$x0),
        .x1(h$6$x1),
        .w(h$6$w),
        .y(h$6$y)
    );
    texture_path$unit$filter$level$1$h$7 h$7(
        .x0(h$7$x0),
        .x1(h$7$x1),
        .w(h$7$w),
        .y(h$7$y)
    );
    texture_path$unit$filter$level$1$h_r$0 h_r$0(
        .d(h_r$0$d),
        .q(h_r$0$q),
        .clock(h_r$0$clock)
    );
    texture_path$unit$filter$level$1$h_r$1 h_r$1(
        .d(h_r$1$d),
        .q(h_r$1$q),
        .clock(h_r$1$clock)
    );
    texture_path$unit$filter$level$1$h_r$2 h_r$2(
        .d(h_r$2$d),
        .q(h_r$2$q),
        .clock(h_r$2$clock)
    );
    texture_path$unit$filter$level$1$h_r$3 h_r$3(
        .d(h_r$3$d),
        .q(h_r$3$q),
        .clock(h_r$3$clock)
    );
    texture_path$unit$filter$level$1$h_r$4 h_r$4(
        .d(h_r$4$d),
        .q(h_r$4$q),
        .clock(h_r$4$clock)
    );
    texture_path$unit$filter$level$1$h_r$5 h_r$5(
        .d(h_r$5$d),
        .q(h_r$5$q),
        .clock(h_r$5$clock)
    );
    texture_path$unit$filter$level$1$h_r$6 h_r$6(
        .d(h_r$6$d),
        .q(h_r$6$q),
        .clock(h_r$6$clock)
    );
    texture_path$unit$filter$level$1$h_r$7 h_r$7(
        .d(h_r$7$d),
        .q(h_r$7$q),
        .clock(h_r$7$clock)
    );
    texture_path$unit$filter$level$1$b_r b_r(
        .d(b_r$d),
        .q(b_r$q),
        .clock(b_r$clock)
    );
    texture_path$unit$filter$level$1$v$0 v$0(
        .x0(v$0$x0),
        .x1(v$0$x1),
        .w(v$0$w),
        .y(v$0$y)
    );
    texture_path$unit$filter$level$1$v$1 v$1(
        .x0(v$1$x0),
        .x1(v$1$x1),
        .w(v$1$w),
        .y(v$1$y)
    );
    texture_path$unit$filter$level$1$v$2 v$2(
        .x0(v$2$x0),
        .x1(v$2$x1),
        .w(v$2$w),
        .y(v$2$y)
    );
    texture_path$unit$filter$level$1$v$3 v$3(
        .x0(v$3$x0),
        .x1(v$3$x1),
        .w(v$3$w),
        .y(v$3$y)
    );
    texture_path$unit$filter$level$1$round$0 round$0(
        .x(round$0$x),
        .y(round$0$y)
    );
    texture_path$unit$filter$level$1$round$1 round$1(
        .x(round$1$x),
        .y(round$1$y)
    );
    texture_path$unit$filter$level$1$round$2 round$2(
        .x(round$2$x),
        .y(round$2$y)
    );
    texture_path$unit$filter$level$1$round$3 round$3(
        .x(round$3$x),
        .y(round$3$y)
    );
    texture_path$unit$filter$level$1$c_r$0 c_r$0(
        .d(c_r$0$d),
        .q(c_r$0$q),
        .clock(c_r$0$clock)
    );
    texture_path$unit$filter$level$1$c_r$1 c_r$1(
        .d(c_r$1$d),
        .q(c_r$1$q),
        .clock(c_r$1$clock)
    );
    texture_path$unit$filter$level$1$c_r$2 c_r$2(
        .d(c_r$2$d),
        .q(c_r$2$q),
        .clock(c_r$2$clock)
    );
    texture_path$unit$filter$level$1$c_r$3 c_r$3(
        .d(c_r$3$d),
        .q(c_r$3$q),
        .clock(c_r$3$clock)
    );
    
    // Update code
    always @(*) begin
        b_r$clock = clock;
        b_r$d = b_r$q;
        h_r$0$clock = clock;
        h_r$0$d = h_r$0$q;
        h_r$1$clock = clock;
        h_r$1$d = h_r$1$q;
        h_r$2$clock = clock;
        h_r$2$d = h_r$2$q;
        h_r$3$clock = clock;
        h_r$3$d = h_r$3$q;
        h_r$4$clock = clock;
        h_r$4$d = h_r$4$q;
        h_r$5$clock = clock;
        h_r$5$d = h_r$5$q;
        h_r$6$clock = clock;
        h_r$6$d = h_r$6$q;
        h_r$7$clock = clock;
        h_r$7$d = h_r$7$q;
        c_r$0$clock = clock;
        c_r$0$d = c_r$0$q;
        c_r$1$clock = clock;
        c_r$1$d = c_r$1$q;
        c_r$2$clock = clock;
        c_r$2$d = c_r$2$q;
        c_r$3$clock = clock;
        c_r$3$d = c_r$3$q;
        h$0$x0 = t0[(0 * 32'h8)+:(8)];
        h$0$x1 = t1[(0 * 32'h8)+:(8)];
        h$0$w = a;
        h$4$x0 = t2[(0 * 32'h8)+:(8)];
        h$4$x1 = t3[(0 * 32'h8)+:(8)];
        h$4$w = a;
        v$0$x0 = h_r$0$q;
        v$0$x1 = h_r$4$q;
        v$0$w = b_r$q;
        round$0$x = v$0$y;
        h$1$x0 = t0[(1 * 32'h8)+:(8)];
        h$1$x1 = t1[(1 * 32'h8)+:(8)];
        h$1$w = a;
        h$5$x0 = t2[(1 * 32'h8)+:(8)];
        h$5$x1 = t3[(1 * 32'h8)+:(8)];
        h$5$w = a;
        v$1$x0 = h_r$1$q;
        v$1$x1 = h_r$5$q;
        v$1$w = b_r$q;
        round$1$x = v$1$y;
        h$2$x0 = t0[(2 * 32'h8)+:(8)];
        h$2$x1 = t1[(2 * 32'h8)+:(8)];
        h$2$w = a;
        h$6$x0 = t2[(2 * 32'h8)+:(8)];
        h$6$x1 = t3[(2 * 32'h8)+:(8)];
        h$6$w = a;
        v$2$x0 = h_r$2$q;
        v$2$x1 = h_r$6$q;
        v$2$w = b_r$q;
        round$2$x = v$2$y;
        h$3$x0 = t0[(3 * 32'h8)+:(8)];
        h$3$x1 = t1[(3 * 32'h8)+:(8)];
        h$3$w = a;
        h$7$x0 = t2[(3 * 32'h8)+:(8)];
        h$7$x1 = t3[(3 * 32'h8)+:(8)];
        h$7$w = a;
        v$3$x0 = h_r$3$q;
        v$3$x1 = h_r$7$q;
        v$3$w = b_r$q;
        round$3$x = v$3$y;
        if (en) begin
            h_r$0$d = h$0$y;
            h_r$1$d = h$1$y;
            h_r$2$d = h$2$y;
            h_r$3$d = h$3$y;
            h_r$4$d = h$4$y;
            h_r$5$d = h$5$y;
            h_r$6$d = h$6$y;
            h_r$7$d = h$7$y;
            b_r$d = b;
            c_r$0$d = round$0$y;
            c_r$1$d = round$1$y;
            c_r$2$d = round$2$y;
            c_r$3$d = round$3$y;
        end
        c = (((c_r$3$q) & 32'hffffffff) << 32'h18) | (((c_r$2$q) & 32'hffffffff) << 32'h10) | (((c_r$1$q) & 32'hffffffff) << 32'h8) | ((c_r$0$q) & 32'hffffffff);
    end
    
endmodule // texture_path$unit$filter$level$1


module texture_path$unit$filter$level$1$b_r(d,q,clock);
    
    // Module arguments
    input wire  [8:0] d;
    output reg  [8:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 9'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$level$1$b_r


module texture_path$unit$filter$level$1$c_r$0(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$level$1$c_r$0


module texture_path$unit$filter$level$1$c_r$1(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$level$1$c_r$1


module texture_path$unit$filter$level$1$c_r$2(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$level$1$c_r$2


module texture_path$unit$filter$level$1$c_r$3(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$level$1$c_r$3


module texture_path$unit$filter$level$1$h$0(x0,x1,w,y);
    
    // Module arguments
    input wire  [7:0] x0;
    input wire  [7:0] x1;
    input wire  [8:0] w;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  s = 8'h8;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [9:0] mul$b;
    wire  [16:0] mul$p;
    
    // Sub module instances
    texture_path$unit$filter$level$1$h$0$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 9'h1ff) - ((x0) & 9'h1ff);
        mul$b = ((w) & 10'h3ff);
        y = (((((x0) & 17'h1ffff) << s) + mul$p) & 16'hffff);
    end
    
endmodule // texture_path$unit$filter$level$1$h$0


module texture_path$unit$filter$level$1$h$0$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [9:0] b;
    output reg  [16:0] p;
    
    // Update code (custom)
    // p = low 17 bits of a * b, both signed: a signed 17-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_path$unit$filter$level$1$h$0$mul


module texture_path$unit$filter$level$1$h$1(x0,x1,w,y);
    
    // Module arguments
    input wire  [7:0] x0;
    input wire  [7:0] x1;
    input wire  [8:0] w;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  s = 8'h8;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [9:0] mul$b;
    wire  [16:0] mul$p;
    
    // Sub module instances
    texture_path$unit$filter$level$1$h$1$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 9'h1ff) - ((x0) & 9'h1ff);
        mul$b = ((w) & 10'h3ff);
        y = (((((x0) & 17'h1ffff) << s) + mul$p) & 16'hffff);
    end
    
endmodule // texture_path$unit$filter$level$1$h$1


module texture_path$unit$filter$level$1$h$1$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [9:0] b;
    output reg  [16:0] p;
    
    // Update code (custom)
    // p = low 17 bits of a * b, both signed: a signed 17-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_path$unit$filter$level$1$h$1$mul


module texture_path$unit$filter$level$1$h$2(x0,x1,w,y);
    
    // Module arguments
    input wire  [7:0] x0;
    input wire  [7:0] x1;
    input wire  [8:0] w;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  s = 8'h8;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [9:0] mul$b;
    wire  [16:0] mul$p;
    
    // Sub module instances
    texture_path$unit$filter$level$1$h$2$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 9'h1ff) - ((x0) & 9'h1ff);
        mul$b = ((w) & 10'h3ff);
        y = (((((x0) & 17'h1ffff) << s) + mul$p) & 16'hffff);
    end
    
endmodule // texture_path$unit$filter$level$1$h$2


module texture_path$unit$filter$level$1$h$2$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [9:0] b;
    output reg  [16:0] p;
    
    // Update code (custom)
    // p = low 17 bits of a * b, both signed: a signed 17-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_path$unit$filter$level$1$h$2$mul


module texture_path$unit$filter$level$1$h$3(x0,x1,w,y);
    
    // Module arguments
    input wire  [7:0] x0;
    input wire  [7:0] x1;
    input wire  [8:0] w;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  s = 8'h8;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [9:0] mul$b;
    wire  [16:0] mul$p;
    
    // Sub module instances
    texture_path$unit$filter$level$1$h$3$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 9'h1ff) - ((x0) & 9'h1ff);
        mul$b = ((w) & 10'h3ff);
        y = (((((x0) & 17'h1ffff) << s) + mul$p) & 16'hffff);
    end
    
endmodule // texture_path$unit$filter$level$1$h$3


module texture_path$unit$filter$level$1$h$3$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [9:0] b;
    output reg  [16:0] p;
    
    // Update code (custom)
    // p = low 17 bits of a * b, both signed: a signed 17-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_path$unit$filter$level$1$h$3$mul


module texture_path$unit$filter$level$1$h$4(x0,x1,w,y);
    
    // Module arguments
    input wire  [7:0] x0;
    input wire  [7:0] x1;
    input wire  [8:0] w;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  s = 8'h8;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [9:0] mul$b;
    wire  [16:0] mul$p;
    
    // Sub module instances
    texture_path$unit$filter$level$1$h$4$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 9'h1ff) - ((x0) & 9'h1ff);
        mul$b = ((w) & 10'h3ff);
        y = (((((x0) & 17'h1ffff) << s) + mul$p) & 16'hffff);
    end
    
endmodule // texture_path$unit$filter$level$1$h$4


module texture_path$unit$filter$level$1$h$4$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [9:0] b;
    output reg  [16:0] p;
    
    // Update code (custom)
    // p = low 17 bits of a * b, both signed: a signed 17-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_path$unit$filter$level$1$h$4$mul


module texture_path$unit$filter$level$1$h$5(x0,x1,w,y);
    
    // Module arguments
    input wire  [7:0] x0;
    input wire  [7:0] x1;
    input wire  [8:0] w;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  s = 8'h8;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [9:0] mul$b;
    wire  [16:0] mul$p;
    
    // Sub module instances
    texture_path$unit$filter$level$1$h$5$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 9'h1ff) - ((x0) & 9'h1ff);
        mul$b = ((w) & 10'h3ff);
        y = (((((x0) & 17'h1ffff) << s) + mul$p) & 16'hffff);
    end
    
endmodule // texture_path$unit$filter$level$1$h$5


module texture_path$unit$filter$level$1$h$5$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [9:0] b;
    output reg  [16:0] p;
    
    // Update code (custom)
    // p = low 17 bits of a * b, both signed: a signed 17-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_path$unit$filter$level$1$h$5$mul


module texture_path$unit$filter$level$1$h$6(x0,x1,w,y);
    
    // Module arguments
    input wire  [7:0] x0;
    input wire  [7:0] x1;
    input wire  [8:0] w;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  s = 8'h8;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [9:0] mul$b;
    wire  [16:0] mul$p;
    
    // Sub module instances
    texture_path$unit$filter$level$1$h$6$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 9'h1ff) - ((x0) & 9'h1ff);
        mul$b = ((w) & 10'h3ff);
        y = (((((x0) & 17'h1ffff) << s) + mul$p) & 16'hffff);
    end
    
endmodule // texture_path$unit$filter$level$1$h$6


module texture_path$unit$filter$level$1$h$6$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [9:0] b;
    output reg  [16:0] p;
    
    // Update code (custom)
    // p = low 17 bits of a * b, both signed: a signed 17-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_path$unit$filter$level$1$h$6$mul


module texture_path$unit$filter$level$1$h$7(x0,x1,w,y);
    
    // Module arguments
    input wire  [7:0] x0;
    input wire  [7:0] x1;
    input wire  [8:0] w;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  s = 8'h8;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [9:0] mul$b;
    wire  [16:0] mul$p;
    
    // Sub module instances
    texture_path$unit$filter$level$1$h$7$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 9'h1ff) - ((x0) & 9'h1ff);
        mul$b = ((w) & 10'h3ff);
        y = (((((x0) & 17'h1ffff) << s) + mul$p) & 16'hffff);
    end
    
endmodule // texture_path$unit$filter$level$1$h$7


module texture_path$unit$filter$level$1$h$7$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [9:0] b;
    output reg  [16:0] p;
    
    // Update code (custom)
    // p = low 17 bits of a * b, both signed: a signed 17-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_path$unit$filter$level$1$h$7$mul


module texture_path$unit$filter$level$1$h_r$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$level$1$h_r$0


module texture_path$unit$filter$level$1$h_r$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$level$1$h_r$1


module texture_path$unit$filter$level$1$h_r$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$level$1$h_r$2


module texture_path$unit$filter$level$1$h_r$3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$level$1$h_r$3


module texture_path$unit$filter$level$1$h_r$4(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$level$1$h_r$4


module texture_path$unit$filter$level$1$h_r$5(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$level$1$h_r$5


module texture_path$unit$filter$level$1$h_r$6(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$level$1$h_r$6


module texture_path$unit$filter$level$1$h_r$7(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$level$1$h_r$7


module texture_path$unit$filter$level$1$round$0(x,y);
    
    // Module arguments
    input wire  [23:0] x;
    output reg  [7:0] y;
    
    // Constant declarations
    localparam  half = 24'h8000;
    localparam  shift = 8'h10;
    
    // Update code
    always @(*) begin
        y = (((x + half) >> shift) & 8'hff);
    end
    
endmodule // texture_path$unit$filter$level$1$round$0


module texture_path$unit$filter$level$1$round$1(x,y);
    
    // Module arguments
    input wire  [23:0] x;
    output reg  [7:0] y;
    
    // Constant declarations
    localparam  half = 24'h8000;
    localparam  shift = 8'h10;
    
    // Update code
    always @(*) begin
        y = (((x + half) >> shift) & 8'hff);
    end
    
endmodule // texture_path$unit$filter$level$1$round$1


module texture_path$unit$filter$level$1$round$2(x,y);
    
    // Module arguments
    input wire  [23:0] x;
    output reg  [7:0] y;
    
    // Constant declarations
    localparam  half = 24'h8000;
    localparam  shift = 8'h10;
    
    // Update code
    always @(*) begin
        y = (((x + half) >> shift) & 8'hff);
    end
    
endmodule // texture_path$unit$filter$level$1$round$2


module texture_path$unit$filter$level$1$round$3(x,y);
    
    // Module arguments
    input wire  [23:0] x;
    output reg  [7:0] y;
    
    // Constant declarations
    localparam  half = 24'h8000;
    localparam  shift = 8'h10;
    
    // Update code
    always @(*) begin
        y = (((x + half) >> shift) & 8'hff);
    end
    
endmodule // texture_path$unit$filter$level$1$round$3


module texture_path$unit$filter$level$1$v$0(x0,x1,w,y);
    
    // Module arguments
    input wire  [15:0] x0;
    input wire  [15:0] x1;
    input wire  [8:0] w;
    output reg  [23:0] y;
    
    // Constant declarations
    localparam  s = 8'h8;
    
    // Stub signals
    reg  [16:0] mul$a;
    reg  [9:0] mul$b;
    wire  [24:0] mul$p;
    
    // Sub module instances
    texture_path$unit$filter$level$1$v$0$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 17'h1ffff) - ((x0) & 17'h1ffff);
        mul$b = ((w) & 10'h3ff);
        y = (((((x0) & 25'h1ffffff) << s) + mul$p) & 24'hffffff);
    end
    
endmodule // texture_path$unit$filter$level$1$v$0


module texture_path$unit$filter$level$1$v$0$mul(a,b,p);
    
    // Module arguments
    input wire  [16:0] a;
    input wire  [9:0] b;
    output reg  [24:0] p;
    
    // Update code (custom)
    // p = low 25 bits of a * b, both signed: a signed 25-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_path$unit$filter$level$1$v$0$mul


module texture_path$unit$filter$level$1$v$1(x0,x1,w,y);
    
    // Module arguments
    input wire  [15:0] x0;
    input wire  [15:0] x1;
    input wire  [8:0] w;
    output reg  [23:0] y;
    
    // Constant declarations
    localparam  s = 8'h8;
    
    // Stub signals
    reg  [16:0] mul$a;
    reg  [9:0] mul$b;
    wire  [24:0] mul$p;
    
    // Sub module instances
    texture_path$unit$filter$level$1$v$1$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 17'h1ffff) - ((x0) & 17'h1ffff);
        mul$b = ((w) & 10'h3ff);
        y = (((((x0) & 25'h1ffffff) << s) + mul$p) & 24'hffffff);
    end
    
endmodule // texture_path$unit$filter$level$1$v$1


module texture_path$unit$filter$level$1$v$1$mul(a,b,p);
    
    // Module arguments
    input wire  [16:0] a;
    input wire  [9:0] b;
    output reg  [24:0] p;
    
    // Update code (custom)
    // p = low 25 bits of a * b, both signed: a signed 25-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_path$unit$filter$level$1$v$1$mul


module texture_path$unit$filter$level$1$v$2(x0,x1,w,y);
    
    // Module arguments
    input wire  [15:0] x0;
    input wire  [15:0] x1;
    input wire  [8:0] w;
    output reg  [23:0] y;
    
    // Constant declarations
    localparam  s = 8'h8;
    
    // Stub signals
    reg  [16:0] mul$a;
    reg  [9:0] mul$b;
    wire  [24:0] mul$p;
    
    // Sub module instances
    texture_path$unit$filter$level$1$v$2$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 17'h1ffff) - ((x0) & 17'h1ffff);
        mul$b = ((w) & 10'h3ff);
        y = (((((x0) & 25'h1ffffff) << s) + mul$p) & 24'hffffff);
    end
    
endmodule // texture_path$unit$filter$level$1$v$2


module texture_path$unit$filter$level$1$v$2$mul(a,b,p);
    
    // Module arguments
    input wire  [16:0] a;
    input wire  [9:0] b;
    output reg  [24:0] p;
    
    // Update code (custom)
    // p = low 25 bits of a * b, both signed: a signed 25-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_path$unit$filter$level$1$v$2$mul


module texture_path$unit$filter$level$1$v$3(x0,x1,w,y);
    
    // Module arguments
    input wire  [15:0] x0;
    input wire  [15:0] x1;
    input wire  [8:0] w;
    output reg  [23:0] y;
    
    // Constant declarations
    localparam  s = 8'h8;
    
    // Stub signals
    reg  [16:0] mul$a;
    reg  [9:0] mul$b;
    wire  [24:0] mul$p;
    
    // Sub module instances
    texture_path$unit$filter$level$1$v$3$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 17'h1ffff) - ((x0) & 17'h1ffff);
        mul$b = ((w) & 10'h3ff);
        y = (((((x0) & 25'h1ffffff) << s) + mul$p) & 24'hffffff);
    end
    
endmodule // texture_path$unit$filter$level$1$v$3


module texture_path$unit$filter$level$1$v$3$mul(a,b,p);
    
    // Module arguments
    input wire  [16:0] a;
    input wire  [9:0] b;
    output reg  [24:0] p;
    
    // Update code (custom)
    // p = low 25 bits of a * b, both signed: a signed 25-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_path$unit$filter$level$1$v$3$mul


module texture_path$unit$filter$mix$0(x0,x1,w,y);
    
    // Module arguments
    input wire  [7:0] x0;
    input wire  [7:0] x1;
    input wire  [6:0] w;
    output reg  [13:0] y;
    
    // Constant declarations
    localparam  s = 8'h6;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [7:0] mul$b;
    wire  [14:0] mul$p;
    
    // Sub module instances
    texture_path$unit$filter$mix$0$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 9'h1ff) - ((x0) & 9'h1ff);
        mul$b = ((w) & 8'hff);
        y = (((((x0) & 15'h7fff) << s) + mul$p) & 14'h3fff);
    end
    
endmodule // texture_path$unit$filter$mix$0


module texture_path$unit$filter$mix$0$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [7:0] b;
    output reg  [14:0] p;
    
    // Update code (custom)
    // p = low 15 bits of a * b, both signed: a signed 15-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_path$unit$filter$mix$0$mul


module texture_path$unit$filter$mix$1(x0,x1,w,y);
    
    // Module arguments
    input wire  [7:0] x0;
    input wire  [7:0] x1;
    input wire  [6:0] w;
    output reg  [13:0] y;
    
    // Constant declarations
    localparam  s = 8'h6;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [7:0] mul$b;
    wire  [14:0] mul$p;
    
    // Sub module instances
    texture_path$unit$filter$mix$1$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 9'h1ff) - ((x0) & 9'h1ff);
        mul$b = ((w) & 8'hff);
        y = (((((x0) & 15'h7fff) << s) + mul$p) & 14'h3fff);
    end
    
endmodule // texture_path$unit$filter$mix$1


module texture_path$unit$filter$mix$1$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [7:0] b;
    output reg  [14:0] p;
    
    // Update code (custom)
    // p = low 15 bits of a * b, both signed: a signed 15-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_path$unit$filter$mix$1$mul


module texture_path$unit$filter$mix$2(x0,x1,w,y);
    
    // Module arguments
    input wire  [7:0] x0;
    input wire  [7:0] x1;
    input wire  [6:0] w;
    output reg  [13:0] y;
    
    // Constant declarations
    localparam  s = 8'h6;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [7:0] mul$b;
    wire  [14:0] mul$p;
    
    // Sub module instances
    texture_path$unit$filter$mix$2$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 9'h1ff) - ((x0) & 9'h1ff);
        mul$b = ((w) & 8'hff);
        y = (((((x0) & 15'h7fff) << s) + mul$p) & 14'h3fff);
    end
    
endmodule // texture_path$unit$filter$mix$2


module texture_path$unit$filter$mix$2$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [7:0] b;
    output reg  [14:0] p;
    
    // Update code (custom)
    // p = low 15 bits of a * b, both signed: a signed 15-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_path$unit$filter$mix$2$mul


module texture_path$unit$filter$mix$3(x0,x1,w,y);
    
    // Module arguments
    input wire  [7:0] x0;
    input wire  [7:0] x1;
    input wire  [6:0] w;
    output reg  [13:0] y;
    
    // Constant declarations
    localparam  s = 8'h6;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [7:0] mul$b;
    wire  [14:0] mul$p;
    
    // Sub module instances
    texture_path$unit$filter$mix$3$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 9'h1ff) - ((x0) & 9'h1ff);
        mul$b = ((w) & 8'hff);
        y = (((((x0) & 15'h7fff) << s) + mul$p) & 14'h3fff);
    end
    
endmodule // texture_path$unit$filter$mix$3


module texture_path$unit$filter$mix$3$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [7:0] b;
    output reg  [14:0] p;
    
    // Update code (custom)
    // p = low 15 bits of a * b, both signed: a signed 15-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_path$unit$filter$mix$3$mul


module texture_path$unit$filter$mix_round$0(x,y);
    
    // Module arguments
    input wire  [13:0] x;
    output reg  [7:0] y;
    
    // Constant declarations
    localparam  half = 14'b100000;
    localparam  shift = 8'h6;
    
    // Update code
    always @(*) begin
        y = (((x + half) >> shift) & 8'hff);
    end
    
endmodule // texture_path$unit$filter$mix_round$0


module texture_path$unit$filter$mix_round$1(x,y);
    
    // Module arguments
    input wire  [13:0] x;
    output reg  [7:0] y;
    
    // Constant declarations
    localparam  half = 14'b100000;
    localparam  shift = 8'h6;
    
    // Update code
    always @(*) begin
        y = (((x + half) >> shift) & 8'hff);
    end
    
endmodule // texture_path$unit$filter$mix_round$1


module texture_path$unit$filter$mix_round$2(x,y);
    
    // Module arguments
    input wire  [13:0] x;
    output reg  [7:0] y;
    
    // Constant declarations
    localparam  half = 14'b100000;
    localparam  shift = 8'h6;
    
    // Update code
    always @(*) begin
        y = (((x + half) >> shift) & 8'hff);
    end
    
endmodule // texture_path$unit$filter$mix_round$2


module texture_path$unit$filter$mix_round$3(x,y);
    
    // Module arguments
    input wire  [13:0] x;
    output reg  [7:0] y;
    
    // Constant declarations
    localparam  half = 14'b100000;
    localparam  shift = 8'h6;
    
    // Update code
    always @(*) begin
        y = (((x + half) >> shift) & 8'hff);
    end
    
endmodule // texture_path$unit$filter$mix_round$3


module texture_path$unit$filter$s1_a$0(d,q,clock);
    
    // Module arguments
    input wire  [8:0] d;
    output reg  [8:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 9'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$s1_a$0


module texture_path$unit$filter$s1_a$1(d,q,clock);
    
    // Module arguments
    input wire  [8:0] d;
    output reg  [8:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 9'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$s1_a$1


module texture_path$unit$filter$s1_b$0(d,q,clock);
    
    // Module arguments
    input wire  [8:0] d;
    output reg  [8:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 9'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$s1_b$0


module texture_path$unit$filter$s1_b$1(d,q,clock);
    
    // Module arguments
    input wire  [8:0] d;
    output reg  [8:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 9'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$s1_b$1


module texture_path$unit$filter$s1_cf(d,q,clock);
    
    // Module arguments
    input wire  [23:0] d;
    output reg  [23:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 24'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$s1_cf


module texture_path$unit$filter$s1_env(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$s1_env


module texture_path$unit$filter$s1_frac(d,q,clock);
    
    // Module arguments
    input wire  [5:0] d;
    output reg  [5:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 6'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$s1_frac


module texture_path$unit$filter$s1_texel$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$s1_texel$0


module texture_path$unit$filter$s1_texel$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$s1_texel$1


module texture_path$unit$filter$s1_texel$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$s1_texel$2


module texture_path$unit$filter$s1_texel$3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$s1_texel$3


module texture_path$unit$filter$s1_texel$4(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$s1_texel$4


module texture_path$unit$filter$s1_texel$5(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$s1_texel$5


module texture_path$unit$filter$s1_texel$6(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$s1_texel$6


module texture_path$unit$filter$s1_texel$7(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$s1_texel$7


module texture_path$unit$filter$s1_two(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$s1_two


module texture_path$unit$filter$s1_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$s1_valid


module texture_path$unit$filter$s2_cf(d,q,clock);
    
    // Module arguments
    input wire  [23:0] d;
    output reg  [23:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 24'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$s2_cf


module texture_path$unit$filter$s2_env(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$s2_env


module texture_path$unit$filter$s2_frac(d,q,clock);
    
    // Module arguments
    input wire  [5:0] d;
    output reg  [5:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 6'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$s2_frac


module texture_path$unit$filter$s2_two(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$s2_two


module texture_path$unit$filter$s2_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$s2_valid


module texture_path$unit$filter$s3_cf(d,q,clock);
    
    // Module arguments
    input wire  [23:0] d;
    output reg  [23:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 24'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$s3_cf


module texture_path$unit$filter$s3_env(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$s3_env


module texture_path$unit$filter$s3_frac(d,q,clock);
    
    // Module arguments
    input wire  [5:0] d;
    output reg  [5:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 6'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$s3_frac


module texture_path$unit$filter$s3_two(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$s3_two


module texture_path$unit$filter$s3_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$s3_valid


module texture_path$unit$filter$s4_cf(d,q,clock);
    
    // Module arguments
    input wire  [23:0] d;
    output reg  [23:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 24'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$s4_cf


module texture_path$unit$filter$s4_cs$0(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$s4_cs$0


module texture_path$unit$filter$s4_cs$1(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$s4_cs$1


module texture_path$unit$filter$s4_cs$2(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$s4_cs$2


module texture_path$unit$filter$s4_cs$3(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$s4_cs$3


module texture_path$unit$filter$s4_env(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$s4_env


module texture_path$unit$filter$s4_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$s4_valid


module texture_path$unit$filter$s5_rgba(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$s5_rgba


module texture_path$unit$filter$s5_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$filter$s5_valid


module texture_path$unit$filter$weight$0(alpha,gaussian,w);
    
    // Module arguments
    input wire  [7:0] alpha;
    input wire  gaussian;
    output reg  [8:0] w;
    
    // Constant declarations
    localparam  down = 8'h0;
    localparam  up = 8'h0;
    
    // Stub signals
    reg  [7:0] rom$address;
    wire  [8:0] rom$data;
    
    // Sub module instances
    texture_path$unit$filter$weight$0$rom rom(
        .address(rom$address),
        .data(rom$data)
    );
    
    // Update code
    always @(*) begin
        rom$address = alpha;
        w = ((alpha >> down) & 9'h1ff) << up;
        if (gaussian) begin
            w = rom$data;
        end
    end
    
endmodule // texture_path$unit$filter$weight$0


module texture_path$unit$filter$weight$0$rom(address,data);
    
    // Module arguments
    input wire  [7:0] address;
    output reg  [8:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        8'h0: data = 9'b0;
      8'h1: data = 9'b0;
      8'h2: data = 9'b0;
      8'h3: data = 9'b0;
      8'h4: data = 9'b0;
      8'h5: data = 9'b0;
      8'h6: data = 9'b0;
      8'h7: data = 9'b1;
      8'h8: data = 9'b1;
      8'h9: data = 9'b1;
      8'ha: data = 9'b1;
      8'hb: data = 9'b1;
      8'hc: data = 9'b10;
      8'hd: data = 9'b10;
      8'he: data = 9'b10;
      8'hf: data = 9'b11;
      8'h10: data = 9'b11;
      8'h11: data = 9'b11;
      8'h12: data = 9'b100;
      8'h13: data = 9'b100;
      8'h14: data = 9'b100;
      8'h15: data = 9'b101;
      8'h16: data = 9'b101;
      8'h17: data = 9'b110;
      8'h18: data = 9'b110;
      8'h19: data = 9'b111;
      8'h1a: data = 9'b111;
      8'h1b: data = 9'b1000;
      8'h1c: data = 9'b1001;
      8'h1d: data = 9'b1001;
      8'h1e: data = 9'b1010;
      8'h1f: data = 9'b1010;
      8'h20: data = 9'b1011;
      8'h21: data = 9'b1100;
      8'h22: data = 9'b1100;
      8'h23: data = 9'b1101;
      8'h24: data = 9'b1110;
      8'h25: data = 9'b1110;
      8'h26: data = 9'b1111;
      8'h27: data = 9'b10000;
      8'h28: data = 9'b10001;
      8'h29: data = 9'b10010;
      8'h2a: data = 9'b10010;
      8'h2b: data = 9'b10011;
      8'h2c: data = 9'b10100;
      8'h2d: data = 9'b10101;
      8'h2e: data = 9'b10110;
      8'h2f: data = 9'b10111;
      8'h30: data = 9'b11000;
      8'h31: data = 9'b11001;
      8'h32: data = 9'b11001;
      8'h33: data = 9'b11010;
      8'h34: data = 9'b11011;
      8'h35: data = 9'b11100;
      8'h36: data = 9'b11101;
      8'h37: data = 9'b11110;
      8'h38: data = 9'b11111;
      8'h39: data = 9'b100000;
      8'h3a: data = 9'b100001;
      8'h3b: data = 9'b100011;
      8'h3c: data = 9'b100100;
      8'h3d: data = 9'b100101;
      8'h3e: data = 9'b100110;
      8'h3f: data = 9'b100111;
      8'h40: data = 9'b101000;
      8'h41: data = 9'b101001;
      8'h42: data = 9'b101010;
      8'h43: data = 9'b101011;
      8'h44: data = 9'b101101;
      8'h45: data = 9'b101110;
      8'h46: data = 9'b101111;
      8'h47: data = 9'b110000;
      8'h48: data = 9'b110001;
      8'h49: data = 9'b110011;
      8'h4a: data = 9'b110100;
      8'h4b: data = 9'b110101;
      8'h4c: data = 9'b110110;
      8'h4d: data = 9'b111000;
      8'h4e: data = 9'b111001;
      8'h4f: data = 9'b111010;
      8'h50: data = 9'b111011;
      8'h51: data = 9'b111101;
      8'h52: data = 9'b111110;
      8'h53: data = 9'b111111;
      8'h54: data = 9'b1000001;
      8'h55: data = 9'b1000010;
      8'h56: data = 9'b1000011;
      8'h57: data = 9'b1000101;
      8'h58: data = 9'b1000110;
      8'h59: data = 9'b1000111;
      8'h5a: data = 9'b1001001;
      8'h5b: data = 9'b1001010;
      8'h5c: data = 9'b1001011;
      8'h5d: data = 9'b1001101;
      8'h5e: data = 9'b1001110;
      8'h5f: data = 9'b1010000;
      8'h60: data = 9'b1010001;
      8'h61: data = 9'b1010010;
      8'h62: data = 9'b1010100;
      8'h63: data = 9'b1010101;
      8'h64: data = 9'b1010111;
      8'h65: data = 9'b1011000;
      8'h66: data = 9'b1011010;
      8'h67: data = 9'b1011011;
      8'h68: data = 9'b1011100;
      8'h69: data = 9'b1011110;
      8'h6a: data = 9'b1011111;
      8'h6b: data = 9'b1100001;
      8'h6c: data = 9'b1100010;
      8'h6d: data = 9'b1100100;
      8'h6e: data = 9'b1100101;
      8'h6f: data = 9'b1100111;
      8'h70: data = 9'b1101000;
      8'h71: data = 9'b1101010;
      8'h72: data = 9'b1101011;
      8'h73: data = 9'b1101101;
      8'h74: data = 9'b1101110;
      8'h75: data = 9'b1110000;
      8'h76: data = 9'b1110001;
      8'h77: data = 9'b1110011;
      8'h78: data = 9'b1110100;
      8'h79: data = 9'b1110110;
      8'h7a: data = 9'b1110111;
      8'h7b: data = 9'b1111001;
      8'h7c: data = 9'b1111010;
      8'h7d: data = 9'b1111100;
      8'h7e: data = 9'b1111101;
      8'h7f: data = 9'b1111111;
      8'h80: data = 9'b10000000;
      8'h81: data = 9'b10000001;
      8'h82: data = 9'b10000011;
      8'h83: data = 9'b10000100;
      8'h84: data = 9'b10000110;
      8'h85: data = 9'b10000111;
      8'h86: data = 9'b10001001;
      8'h87: data = 9'b10001010;
      8'h88: data = 9'b10001100;
      8'h89: data = 9'b10001101;
      8'h8a: data = 9'b10001111;
      8'h8b: data = 9'b10010000;
      8'h8c: data = 9'b10010010;
      8'h8d: data = 9'b10010011;
      8'h8e: data = 9'b10010101;
      8'h8f: data = 9'b10010110;
      8'h90: data = 9'b10011000;
      8'h91: data = 9'b10011001;
      8'h92: data = 9'b10011011;
      8'h93: data = 9'b10011100;
      8'h94: data = 9'b10011110;
      8'h95: data = 9'b10011111;
      8'h96: data = 9'b10100001;
      8'h97: data = 9'b10100010;
      8'h98: data = 9'b10100100;
      8'h99: data = 9'b10100101;
      8'h9a: data = 9'b10100110;
      8'h9b: data = 9'b10101000;
      8'h9c: data = 9'b10101001;
      8'h9d: data = 9'b10101011;
      8'h9e: data = 9'b10101100;
      8'h9f: data = 9'b10101110;
      8'ha0: data = 9'b10101111;
      8'ha1: data = 9'b10110000;
      8'ha2: data = 9'b10110010;
      8'ha3: data = 9'b10110011;
      8'ha4: data = 9'b10110101;
      8'ha5: data = 9'b10110110;
      8'ha6: data = 9'b10110111;
      8'ha7: data = 9'b10111001;
      8'ha8: data = 9'b10111010;
      8'ha9: data = 9'b10111011;
      8'haa: data = 9'b10111101;
      8'hab: data = 9'b10111110;
      8'hac: data = 9'b10111111;
      8'had: data = 9'b11000001;
      8'hae: data = 9'b11000010;
      8'haf: data = 9'b11000011;
      8'hb0: data = 9'b11000101;
      8'hb1: data = 9'b11000110;
      8'hb2: data = 9'b11000111;
      8'hb3: data = 9'b11001000;
      8'hb4: data = 9'b11001010;
      8'hb5: data = 9'b11001011;
      8'hb6: data = 9'b11001100;
      8'hb7: data = 9'b11001101;
      8'hb8: data = 9'b11001111;
      8'hb9: data = 9'b11010000;
      8'hba: data = 9'b11010001;
      8'hbb: data = 9'b11010010;
      8'hbc: data = 9'b11010011;
      8'hbd: data = 9'b11010101;
      8'hbe: data = 9'b11010110;
      8'hbf: data = 9'b11010111;
      8'hc0: data = 9'b11011000;
      8'hc1: data = 9'b11011001;
      8'hc2: data = 9'b11011010;
      8'hc3: data = 9'b11011011;
      8'hc4: data = 9'b11011100;
      8'hc5: data = 9'b11011101;
      8'hc6: data = 9'b11011111;
      8'hc7: data = 9'b11100000;
      8'hc8: data = 9'b11100001;
      8'hc9: data = 9'b11100010;
      8'hca: data = 9'b11100011;
      8'hcb: data = 9'b11100100;
      8'hcc: data = 9'b11100101;
      8'hcd: data = 9'b11100110;
      8'hce: data = 9'b11100111;
      8'hcf: data = 9'b11100111;
      8'hd0: data = 9'b11101000;
      8'hd1: data = 9'b11101001;
      8'hd2: data = 9'b11101010;
      8'hd3: data = 9'b11101011;
      8'hd4: data = 9'b11101100;
      8'hd5: data = 9'b11101101;
      8'hd6: data = 9'b11101110;
      8'hd7: data = 9'b11101110;
      8'hd8: data = 9'b11101111;
      8'hd9: data = 9'b11110000;
      8'hda: data = 9'b11110001;
      8'hdb: data = 9'b11110010;
      8'hdc: data = 9'b11110010;
      8'hdd: data = 9'b11110011;
      8'hde: data = 9'b11110100;
      8'hdf: data = 9'b11110100;
      8'he0: data = 9'b11110101;
      8'he1: data = 9'b11110110;
      8'he2: data = 9'b11110110;
      8'he3: data = 9'b11110111;
      8'he4: data = 9'b11110111;
      8'he5: data = 9'b11111000;
      8'he6: data = 9'b11111001;
      8'he7: data = 9'b11111001;
      8'he8: data = 9'b11111010;
      8'he9: data = 9'b11111010;
      8'hea: data = 9'b11111011;
      8'heb: data = 9'b11111011;
      8'hec: data = 9'b11111100;
      8'hed: data = 9'b11111100;
      8'hee: data = 9'b11111100;
      8'hef: data = 9'b11111101;
      8'hf0: data = 9'b11111101;
      8'hf1: data = 9'b11111101;
      8'hf2: data = 9'b11111110;
      8'hf3: data = 9'b11111110;
      8'hf4: data = 9'b11111110;
      8'hf5: data = 9'b11111111;
      8'hf6: data = 9'b11111111;
      8'hf7: data = 9'b11111111;
      8'hf8: data = 9'b11111111;
      8'hf9: data = 9'b11111111;
      8'hfa: data = 9'b100000000;
      8'hfb: data = 9'b100000000;
      8'hfc: data = 9'b100000000;
      8'hfd: data = 9'b100000000;
      8'hfe: data = 9'b100000000;
      8'hff: data = 9'b100000000;
      default: data = 9'b0;
    endcase
            
endmodule // texture_path$unit$filter$weight$0$rom


module texture_path$unit$filter$weight$1(alpha,gaussian,w);
    
    // Module arguments
    input wire  [7:0] alpha;
    input wire  gaussian;
    output reg  [8:0] w;
    
    // Constant declarations
    localparam  down = 8'h0;
    localparam  up = 8'h0;
    
    // Stub signals
    reg  [7:0] rom$address;
    wire  [8:0] rom$data;
    
    // Sub module instances
    texture_path$unit$filter$weight$1$rom rom(
        .address(rom$address),
        .data(rom$data)
    );
    
    // Update code
    always @(*) begin
        rom$address = alpha;
        w = ((alpha >> down) & 9'h1ff) << up;
        if (gaussian) begin
            w = rom$data;
        end
    end
    
endmodule // texture_path$unit$filter$weight$1


module texture_path$unit$filter$weight$1$rom(address,data);
    
    // Module arguments
    input wire  [7:0] address;
    output reg  [8:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        8'h0: data = 9'b0;
      8'h1: data = 9'b0;
      8'h2: data = 9'b0;
      8'h3: data = 9'b0;
      8'h4: data = 9'b0;
      8'h5: data = 9'b0;
      8'h6: data = 9'b0;
      8'h7: data = 9'b1;
      8'h8: data = 9'b1;
      8'h9: data = 9'b1;
      8'ha: data = 9'b1;
      8'hb: data = 9'b1;
      8'hc: data = 9'b10;
      8'hd: data = 9'b10;
      8'he: data = 9'b10;
      8'hf: data = 9'b11;
      8'h10: data = 9'b11;
      8'h11: data = 9'b11;
      8'h12: data = 9'b100;
      8'h13: data = 9'b100;
      8'h14: data = 9'b100;
      8'h15: data = 9'b101;
      8'h16: data = 9'b101;
      8'h17: data = 9'b110;
      8'h18: data = 9'b110;
      8'h19: data = 9'b111;
      8'h1a: data = 9'b111;
      8'h1b: data = 9'b1000;
      8'h1c: data = 9'b1001;
      8'h1d: data = 9'b1001;
      8'h1e: data = 9'b1010;
      8'h1f: data = 9'b1010;
      8'h20: data = 9'b1011;
      8'h21: data = 9'b1100;
      8'h22: data = 9'b1100;
      8'h23: data = 9'b1101;
      8'h24: data = 9'b1110;
      8'h25: data = 9'b1110;
      8'h26: data = 9'b1111;
      8'h27: data = 9'b10000;
      8'h28: data = 9'b10001;
      8'h29: data = 9'b10010;
      8'h2a: data = 9'b10010;
      8'h2b: data = 9'b10011;
      8'h2c: data = 9'b10100;
      8'h2d: data = 9'b10101;
      8'h2e: data = 9'b10110;
      8'h2f: data = 9'b10111;
      8'h30: data = 9'b11000;
      8'h31: data = 9'b11001;
      8'h32: data = 9'b11001;
      8'h33: data = 9'b11010;
      8'h34: data = 9'b11011;
      8'h35: data = 9'b11100;
      8'h36: data = 9'b11101;
      8'h37: data = 9'b11110;
      8'h38: data = 9'b11111;
      8'h39: data = 9'b100000;
      8'h3a: data = 9'b100001;
      8'h3b: data = 9'b100011;
      8'h3c: data = 9'b100100;
      8'h3d: data = 9'b100101;
      8'h3e: data = 9'b100110;
      8'h3f: data = 9'b100111;
      8'h40: data = 9'b101000;
      8'h41: data = 9'b101001;
      8'h42: data = 9'b101010;
      8'h43: data = 9'b101011;
      8'h44: data = 9'b101101;
      8'h45: data = 9'b101110;
      8'h46: data = 9'b101111;
      8'h47: data = 9'b110000;
      8'h48: data = 9'b110001;
      8'h49: data = 9'b110011;
      8'h4a: data = 9'b110100;
      8'h4b: data = 9'b110101;
      8'h4c: data = 9'b110110;
      8'h4d: data = 9'b111000;
      8'h4e: data = 9'b111001;
      8'h4f: data = 9'b111010;
      8'h50: data = 9'b111011;
      8'h51: data = 9'b111101;
      8'h52: data = 9'b111110;
      8'h53: data = 9'b111111;
      8'h54: data = 9'b1000001;
      8'h55: data = 9'b1000010;
      8'h56: data = 9'b1000011;
      8'h57: data = 9'b1000101;
      8'h58: data = 9'b1000110;
      8'h59: data = 9'b1000111;
      8'h5a: data = 9'b1001001;
      8'h5b: data = 9'b1001010;
      8'h5c: data = 9'b1001011;
      8'h5d: data = 9'b1001101;
      8'h5e: data = 9'b1001110;
      8'h5f: data = 9'b1010000;
      8'h60: data = 9'b1010001;
      8'h61: data = 9'b1010010;
      8'h62: data = 9'b1010100;
      8'h63: data = 9'b1010101;
      8'h64: data = 9'b1010111;
      8'h65: data = 9'b1011000;
      8'h66: data = 9'b1011010;
      8'h67: data = 9'b1011011;
      8'h68: data = 9'b1011100;
      8'h69: data = 9'b1011110;
      8'h6a: data = 9'b1011111;
      8'h6b: data = 9'b1100001;
      8'h6c: data = 9'b1100010;
      8'h6d: data = 9'b1100100;
      8'h6e: data = 9'b1100101;
      8'h6f: data = 9'b1100111;
      8'h70: data = 9'b1101000;
      8'h71: data = 9'b1101010;
      8'h72: data = 9'b1101011;
      8'h73: data = 9'b1101101;
      8'h74: data = 9'b1101110;
      8'h75: data = 9'b1110000;
      8'h76: data = 9'b1110001;
      8'h77: data = 9'b1110011;
      8'h78: data = 9'b1110100;
      8'h79: data = 9'b1110110;
      8'h7a: data = 9'b1110111;
      8'h7b: data = 9'b1111001;
      8'h7c: data = 9'b1111010;
      8'h7d: data = 9'b1111100;
      8'h7e: data = 9'b1111101;
      8'h7f: data = 9'b1111111;
      8'h80: data = 9'b10000000;
      8'h81: data = 9'b10000001;
      8'h82: data = 9'b10000011;
      8'h83: data = 9'b10000100;
      8'h84: data = 9'b10000110;
      8'h85: data = 9'b10000111;
      8'h86: data = 9'b10001001;
      8'h87: data = 9'b10001010;
      8'h88: data = 9'b10001100;
      8'h89: data = 9'b10001101;
      8'h8a: data = 9'b10001111;
      8'h8b: data = 9'b10010000;
      8'h8c: data = 9'b10010010;
      8'h8d: data = 9'b10010011;
      8'h8e: data = 9'b10010101;
      8'h8f: data = 9'b10010110;
      8'h90: data = 9'b10011000;
      8'h91: data = 9'b10011001;
      8'h92: data = 9'b10011011;
      8'h93: data = 9'b10011100;
      8'h94: data = 9'b10011110;
      8'h95: data = 9'b10011111;
      8'h96: data = 9'b10100001;
      8'h97: data = 9'b10100010;
      8'h98: data = 9'b10100100;
      8'h99: data = 9'b10100101;
      8'h9a: data = 9'b10100110;
      8'h9b: data = 9'b10101000;
      8'h9c: data = 9'b10101001;
      8'h9d: data = 9'b10101011;
      8'h9e: data = 9'b10101100;
      8'h9f: data = 9'b10101110;
      8'ha0: data = 9'b10101111;
      8'ha1: data = 9'b10110000;
      8'ha2: data = 9'b10110010;
      8'ha3: data = 9'b10110011;
      8'ha4: data = 9'b10110101;
      8'ha5: data = 9'b10110110;
      8'ha6: data = 9'b10110111;
      8'ha7: data = 9'b10111001;
      8'ha8: data = 9'b10111010;
      8'ha9: data = 9'b10111011;
      8'haa: data = 9'b10111101;
      8'hab: data = 9'b10111110;
      8'hac: data = 9'b10111111;
      8'had: data = 9'b11000001;
      8'hae: data = 9'b11000010;
      8'haf: data = 9'b11000011;
      8'hb0: data = 9'b11000101;
      8'hb1: data = 9'b11000110;
      8'hb2: data = 9'b11000111;
      8'hb3: data = 9'b11001000;
      8'hb4: data = 9'b11001010;
      8'hb5: data = 9'b11001011;
      8'hb6: data = 9'b11001100;
      8'hb7: data = 9'b11001101;
      8'hb8: data = 9'b11001111;
      8'hb9: data = 9'b11010000;
      8'hba: data = 9'b11010001;
      8'hbb: data = 9'b11010010;
      8'hbc: data = 9'b11010011;
      8'hbd: data = 9'b11010101;
      8'hbe: data = 9'b11010110;
      8'hbf: data = 9'b11010111;
      8'hc0: data = 9'b11011000;
      8'hc1: data = 9'b11011001;
      8'hc2: data = 9'b11011010;
      8'hc3: data = 9'b11011011;
      8'hc4: data = 9'b11011100;
      8'hc5: data = 9'b11011101;
      8'hc6: data = 9'b11011111;
      8'hc7: data = 9'b11100000;
      8'hc8: data = 9'b11100001;
      8'hc9: data = 9'b11100010;
      8'hca: data = 9'b11100011;
      8'hcb: data = 9'b11100100;
      8'hcc: data = 9'b11100101;
      8'hcd: data = 9'b11100110;
      8'hce: data = 9'b11100111;
      8'hcf: data = 9'b11100111;
      8'hd0: data = 9'b11101000;
      8'hd1: data = 9'b11101001;
      8'hd2: data = 9'b11101010;
      8'hd3: data = 9'b11101011;
      8'hd4: data = 9'b11101100;
      8'hd5: data = 9'b11101101;
      8'hd6: data = 9'b11101110;
      8'hd7: data = 9'b11101110;
      8'hd8: data = 9'b11101111;
      8'hd9: data = 9'b11110000;
      8'hda: data = 9'b11110001;
      8'hdb: data = 9'b11110010;
      8'hdc: data = 9'b11110010;
      8'hdd: data = 9'b11110011;
      8'hde: data = 9'b11110100;
      8'hdf: data = 9'b11110100;
      8'he0: data = 9'b11110101;
      8'he1: data = 9'b11110110;
      8'he2: data = 9'b11110110;
      8'he3: data = 9'b11110111;
      8'he4: data = 9'b11110111;
      8'he5: data = 9'b11111000;
      8'he6: data = 9'b11111001;
      8'he7: data = 9'b11111001;
      8'he8: data = 9'b11111010;
      8'he9: data = 9'b11111010;
      8'hea: data = 9'b11111011;
      8'heb: data = 9'b11111011;
      8'hec: data = 9'b11111100;
      8'hed: data = 9'b11111100;
      8'hee: data = 9'b11111100;
      8'hef: data = 9'b11111101;
      8'hf0: data = 9'b11111101;
      8'hf1: data = 9'b11111101;
      8'hf2: data = 9'b11111110;
      8'hf3: data = 9'b11111110;
      8'hf4: data = 9'b11111110;
      8'hf5: data = 9'b11111111;
      8'hf6: data = 9'b11111111;
      8'hf7: data = 9'b11111111;
      8'hf8: data = 9'b11111111;
      8'hf9: data = 9'b11111111;
      8'hfa: data = 9'b100000000;
      8'hfb: data = 9'b100000000;
      8'hfc: data = 9'b100000000;
      8'hfd: data = 9'b100000000;
      8'hfe: data = 9'b100000000;
      8'hff: data = 9'b100000000;
      default: data = 9'b0;
    endcase
            
endmodule // texture_path$unit$filter$weight$1$rom


module texture_path$unit$filter$weight$2(alpha,gaussian,w);
    
    // Module arguments
    input wire  [7:0] alpha;
    input wire  gaussian;
    output reg  [8:0] w;
    
    // Constant declarations
    localparam  down = 8'h0;
    localparam  up = 8'h0;
    
    // Stub signals
    reg  [7:0] rom$address;
    wire  [8:0] rom$data;
    
    // Sub module instances
    texture_path$unit$filter$weight$2$rom rom(
        .address(rom$address),
        .data(rom$data)
    );
    
    // Update code
    always @(*) begin
        rom$address = alpha;
        w = ((alpha >> down) & 9'h1ff) << up;
        if (gaussian) begin
            w = rom$data;
        end
    end
    
endmodule // texture_path$unit$filter$weight$2


module texture_path$unit$filter$weight$2$rom(address,data);
    
    // Module arguments
    input wire  [7:0] address;
    output reg  [8:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        8'h0: data = 9'b0;
      8'h1: data = 9'b0;
      8'h2: data = 9'b0;
      8'h3: data = 9'b0;
      8'h4: data = 9'b0;
      8'h5: data = 9'b0;
      8'h6: data = 9'b0;
      8'h7: data = 9'b1;
      8'h8: data = 9'b1;
      8'h9: data = 9'b1;
      8'ha: data = 9'b1;
      8'hb: data = 9'b1;
      8'hc: data = 9'b10;
      8'hd: data = 9'b10;
      8'he: data = 9'b10;
      8'hf: data = 9'b11;
      8'h10: data = 9'b11;
      8'h11: data = 9'b11;
      8'h12: data = 9'b100;
      8'h13: data = 9'b100;
      8'h14: data = 9'b100;
      8'h15: data = 9'b101;
      8'h16: data = 9'b101;
      8'h17: data = 9'b110;
      8'h18: data = 9'b110;
      8'h19: data = 9'b111;
      8'h1a: data = 9'b111;
      8'h1b: data = 9'b1000;
      8'h1c: data = 9'b1001;
      8'h1d: data = 9'b1001;
      8'h1e: data = 9'b1010;
      8'h1f: data = 9'b1010;
      8'h20: data = 9'b1011;
      8'h21: data = 9'b1100;
      8'h22: data = 9'b1100;
      8'h23: data = 9'b1101;
      8'h24: data = 9'b1110;
      8'h25: data = 9'b1110;
      8'h26: data = 9'b1111;
      8'h27: data = 9'b10000;
      8'h28: data = 9'b10001;
      8'h29: data = 9'b10010;
      8'h2a: data = 9'b10010;
      8'h2b: data = 9'b10011;
      8'h2c: data = 9'b10100;
      8'h2d: data = 9'b10101;
      8'h2e: data = 9'b10110;
      8'h2f: data = 9'b10111;
      8'h30: data = 9'b11000;
      8'h31: data = 9'b11001;
      8'h32: data = 9'b11001;
      8'h33: data = 9'b11010;
      8'h34: data = 9'b11011;
      8'h35: data = 9'b11100;
      8'h36: data = 9'b11101;
      8'h37: data = 9'b11110;
      8'h38: data = 9'b11111;
      8'h39: data = 9'b100000;
      8'h3a: data = 9'b100001;
      8'h3b: data = 9'b100011;
      8'h3c: data = 9'b100100;
      8'h3d: data = 9'b100101;
      8'h3e: data = 9'b100110;
      8'h3f: data = 9'b100111;
      8'h40: data = 9'b101000;
      8'h41: data = 9'b101001;
      8'h42: data = 9'b101010;
      8'h43: data = 9'b101011;
      8'h44: data = 9'b101101;
      8'h45: data = 9'b101110;
      8'h46: data = 9'b101111;
      8'h47: data = 9'b110000;
      8'h48: data = 9'b110001;
      8'h49: data = 9'b110011;
      8'h4a: data = 9'b110100;
      8'h4b: data = 9'b110101;
      8'h4c: data = 9'b110110;
      8'h4d: data = 9'b111000;
      8'h4e: data = 9'b111001;
      8'h4f: data = 9'b111010;
      8'h50: data = 9'b111011;
      8'h51: data = 9'b111101;
      8'h52: data = 9'b111110;
      8'h53: data = 9'b111111;
      8'h54: data = 9'b1000001;
      8'h55: data = 9'b1000010;
      8'h56: data = 9'b1000011;
      8'h57: data = 9'b1000101;
      8'h58: data = 9'b1000110;
      8'h59: data = 9'b1000111;
      8'h5a: data = 9'b1001001;
      8'h5b: data = 9'b1001010;
      8'h5c: data = 9'b1001011;
      8'h5d: data = 9'b1001101;
      8'h5e: data = 9'b1001110;
      8'h5f: data = 9'b1010000;
      8'h60: data = 9'b1010001;
      8'h61: data = 9'b1010010;
      8'h62: data = 9'b1010100;
      8'h63: data = 9'b1010101;
      8'h64: data = 9'b1010111;
      8'h65: data = 9'b1011000;
      8'h66: data = 9'b1011010;
      8'h67: data = 9'b1011011;
      8'h68: data = 9'b1011100;
      8'h69: data = 9'b1011110;
      8'h6a: data = 9'b1011111;
      8'h6b: data = 9'b1100001;
      8'h6c: data = 9'b1100010;
      8'h6d: data = 9'b1100100;
      8'h6e: data = 9'b1100101;
      8'h6f: data = 9'b1100111;
      8'h70: data = 9'b1101000;
      8'h71: data = 9'b1101010;
      8'h72: data = 9'b1101011;
      8'h73: data = 9'b1101101;
      8'h74: data = 9'b1101110;
      8'h75: data = 9'b1110000;
      8'h76: data = 9'b1110001;
      8'h77: data = 9'b1110011;
      8'h78: data = 9'b1110100;
      8'h79: data = 9'b1110110;
      8'h7a: data = 9'b1110111;
      8'h7b: data = 9'b1111001;
      8'h7c: data = 9'b1111010;
      8'h7d: data = 9'b1111100;
      8'h7e: data = 9'b1111101;
      8'h7f: data = 9'b1111111;
      8'h80: data = 9'b10000000;
      8'h81: data = 9'b10000001;
      8'h82: data = 9'b10000011;
      8'h83: data = 9'b10000100;
      8'h84: data = 9'b10000110;
      8'h85: data = 9'b10000111;
      8'h86: data = 9'b10001001;
      8'h87: data = 9'b10001010;
      8'h88: data = 9'b10001100;
      8'h89: data = 9'b10001101;
      8'h8a: data = 9'b10001111;
      8'h8b: data = 9'b10010000;
      8'h8c: data = 9'b10010010;
      8'h8d: data = 9'b10010011;
      8'h8e: data = 9'b10010101;
      8'h8f: data = 9'b10010110;
      8'h90: data = 9'b10011000;
      8'h91: data = 9'b10011001;
      8'h92: data = 9'b10011011;
      8'h93: data = 9'b10011100;
      8'h94: data = 9'b10011110;
      8'h95: data = 9'b10011111;
      8'h96: data = 9'b10100001;
      8'h97: data = 9'b10100010;
      8'h98: data = 9'b10100100;
      8'h99: data = 9'b10100101;
      8'h9a: data = 9'b10100110;
      8'h9b: data = 9'b10101000;
      8'h9c: data = 9'b10101001;
      8'h9d: data = 9'b10101011;
      8'h9e: data = 9'b10101100;
      8'h9f: data = 9'b10101110;
      8'ha0: data = 9'b10101111;
      8'ha1: data = 9'b10110000;
      8'ha2: data = 9'b10110010;
      8'ha3: data = 9'b10110011;
      8'ha4: data = 9'b10110101;
      8'ha5: data = 9'b10110110;
      8'ha6: data = 9'b10110111;
      8'ha7: data = 9'b10111001;
      8'ha8: data = 9'b10111010;
      8'ha9: data = 9'b10111011;
      8'haa: data = 9'b10111101;
      8'hab: data = 9'b10111110;
      8'hac: data = 9'b10111111;
      8'had: data = 9'b11000001;
      8'hae: data = 9'b11000010;
      8'haf: data = 9'b11000011;
      8'hb0: data = 9'b11000101;
      8'hb1: data = 9'b11000110;
      8'hb2: data = 9'b11000111;
      8'hb3: data = 9'b11001000;
      8'hb4: data = 9'b11001010;
      8'hb5: data = 9'b11001011;
      8'hb6: data = 9'b11001100;
      8'hb7: data = 9'b11001101;
      8'hb8: data = 9'b11001111;
      8'hb9: data = 9'b11010000;
      8'hba: data = 9'b11010001;
      8'hbb: data = 9'b11010010;
      8'hbc: data = 9'b11010011;
      8'hbd: data = 9'b11010101;
      8'hbe: data = 9'b11010110;
      8'hbf: data = 9'b11010111;
      8'hc0: data = 9'b11011000;
      8'hc1: data = 9'b11011001;
      8'hc2: data = 9'b11011010;
      8'hc3: data = 9'b11011011;
      8'hc4: data = 9'b11011100;
      8'hc5: data = 9'b11011101;
      8'hc6: data = 9'b11011111;
      8'hc7: data = 9'b11100000;
      8'hc8: data = 9'b11100001;
      8'hc9: data = 9'b11100010;
      8'hca: data = 9'b11100011;
      8'hcb: data = 9'b11100100;
      8'hcc: data = 9'b11100101;
      8'hcd: data = 9'b11100110;
      8'hce: data = 9'b11100111;
      8'hcf: data = 9'b11100111;
      8'hd0: data = 9'b11101000;
      8'hd1: data = 9'b11101001;
      8'hd2: data = 9'b11101010;
      8'hd3: data = 9'b11101011;
      8'hd4: data = 9'b11101100;
      8'hd5: data = 9'b11101101;
      8'hd6: data = 9'b11101110;
      8'hd7: data = 9'b11101110;
      8'hd8: data = 9'b11101111;
      8'hd9: data = 9'b11110000;
      8'hda: data = 9'b11110001;
      8'hdb: data = 9'b11110010;
      8'hdc: data = 9'b11110010;
      8'hdd: data = 9'b11110011;
      8'hde: data = 9'b11110100;
      8'hdf: data = 9'b11110100;
      8'he0: data = 9'b11110101;
      8'he1: data = 9'b11110110;
      8'he2: data = 9'b11110110;
      8'he3: data = 9'b11110111;
      8'he4: data = 9'b11110111;
      8'he5: data = 9'b11111000;
      8'he6: data = 9'b11111001;
      8'he7: data = 9'b11111001;
      8'he8: data = 9'b11111010;
      8'he9: data = 9'b11111010;
      8'hea: data = 9'b11111011;
      8'heb: data = 9'b11111011;
      8'hec: data = 9'b11111100;
      8'hed: data = 9'b11111100;
      8'hee: data = 9'b11111100;
      8'hef: data = 9'b11111101;
      8'hf0: data = 9'b11111101;
      8'hf1: data = 9'b11111101;
      8'hf2: data = 9'b11111110;
      8'hf3: data = 9'b11111110;
      8'hf4: data = 9'b11111110;
      8'hf5: data = 9'b11111111;
      8'hf6: data = 9'b11111111;
      8'hf7: data = 9'b11111111;
      8'hf8: data = 9'b11111111;
      8'hf9: data = 9'b11111111;
      8'hfa: data = 9'b100000000;
      8'hfb: data = 9'b100000000;
      8'hfc: data = 9'b100000000;
      8'hfd: data = 9'b100000000;
      8'hfe: data = 9'b100000000;
      8'hff: data = 9'b100000000;
      default: data = 9'b0;
    endcase
            
endmodule // texture_path$unit$filter$weight$2$rom


module texture_path$unit$filter$weight$3(alpha,gaussian,w);
    
    // Module arguments
    input wire  [7:0] alpha;
    input wire  gaussian;
    output reg  [8:0] w;
    
    // Constant declarations
    localparam  down = 8'h0;
    localparam  up = 8'h0;
    
    // Stub signals
    reg  [7:0] rom$address;
    wire  [8:0] rom$data;
    
    // Sub module instances
    texture_path$unit$filter$weight$3$rom rom(
        .address(rom$address),
        .data(rom$data)
    );
    
    // Update code
    always @(*) begin
        rom$address = alpha;
        w = ((alpha >> down) & 9'h1ff) << up;
        if (gaussian) begin
            w = rom$data;
        end
    end
    
endmodule // texture_path$unit$filter$weight$3


module texture_path$unit$filter$weight$3$rom(address,data);
    
    // Module arguments
    input wire  [7:0] address;
    output reg  [8:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        8'h0: data = 9'b0;
      8'h1: data = 9'b0;
      8'h2: data = 9'b0;
      8'h3: data = 9'b0;
      8'h4: data = 9'b0;
      8'h5: data = 9'b0;
      8'h6: data = 9'b0;
      8'h7: data = 9'b1;
      8'h8: data = 9'b1;
      8'h9: data = 9'b1;
      8'ha: data = 9'b1;
      8'hb: data = 9'b1;
      8'hc: data = 9'b10;
      8'hd: data = 9'b10;
      8'he: data = 9'b10;
      8'hf: data = 9'b11;
      8'h10: data = 9'b11;
      8'h11: data = 9'b11;
      8'h12: data = 9'b100;
      8'h13: data = 9'b100;
      8'h14: data = 9'b100;
      8'h15: data = 9'b101;
      8'h16: data = 9'b101;
      8'h17: data = 9'b110;
      8'h18: data = 9'b110;
      8'h19: data = 9'b111;
      8'h1a: data = 9'b111;
      8'h1b: data = 9'b1000;
      8'h1c: data = 9'b1001;
      8'h1d: data = 9'b1001;
      8'h1e: data = 9'b1010;
      8'h1f: data = 9'b1010;
      8'h20: data = 9'b1011;
      8'h21: data = 9'b1100;
      8'h22: data = 9'b1100;
      8'h23: data = 9'b1101;
      8'h24: data = 9'b1110;
      8'h25: data = 9'b1110;
      8'h26: data = 9'b1111;
      8'h27: data = 9'b10000;
      8'h28: data = 9'b10001;
      8'h29: data = 9'b10010;
      8'h2a: data = 9'b10010;
      8'h2b: data = 9'b10011;
      8'h2c: data = 9'b10100;
      8'h2d: data = 9'b10101;
      8'h2e: data = 9'b10110;
      8'h2f: data = 9'b10111;
      8'h30: data = 9'b11000;
      8'h31: data = 9'b11001;
      8'h32: data = 9'b11001;
      8'h33: data = 9'b11010;
      8'h34: data = 9'b11011;
      8'h35: data = 9'b11100;
      8'h36: data = 9'b11101;
      8'h37: data = 9'b11110;
      8'h38: data = 9'b11111;
      8'h39: data = 9'b100000;
      8'h3a: data = 9'b100001;
      8'h3b: data = 9'b100011;
      8'h3c: data = 9'b100100;
      8'h3d: data = 9'b100101;
      8'h3e: data = 9'b100110;
      8'h3f: data = 9'b100111;
      8'h40: data = 9'b101000;
      8'h41: data = 9'b101001;
      8'h42: data = 9'b101010;
      8'h43: data = 9'b101011;
      8'h44: data = 9'b101101;
      8'h45: data = 9'b101110;
      8'h46: data = 9'b101111;
      8'h47: data = 9'b110000;
      8'h48: data = 9'b110001;
      8'h49: data = 9'b110011;
      8'h4a: data = 9'b110100;
      8'h4b: data = 9'b110101;
      8'h4c: data = 9'b110110;
      8'h4d: data = 9'b111000;
      8'h4e: data = 9'b111001;
      8'h4f: data = 9'b111010;
      8'h50: data = 9'b111011;
      8'h51: data = 9'b111101;
      8'h52: data = 9'b111110;
      8'h53: data = 9'b111111;
      8'h54: data = 9'b1000001;
      8'h55: data = 9'b1000010;
      8'h56: data = 9'b1000011;
      8'h57: data = 9'b1000101;
      8'h58: data = 9'b1000110;
      8'h59: data = 9'b1000111;
      8'h5a: data = 9'b1001001;
      8'h5b: data = 9'b1001010;
      8'h5c: data = 9'b1001011;
      8'h5d: data = 9'b1001101;
      8'h5e: data = 9'b1001110;
      8'h5f: data = 9'b1010000;
      8'h60: data = 9'b1010001;
      8'h61: data = 9'b1010010;
      8'h62: data = 9'b1010100;
      8'h63: data = 9'b1010101;
      8'h64: data = 9'b1010111;
      8'h65: data = 9'b1011000;
      8'h66: data = 9'b1011010;
      8'h67: data = 9'b1011011;
      8'h68: data = 9'b1011100;
      8'h69: data = 9'b1011110;
      8'h6a: data = 9'b1011111;
      8'h6b: data = 9'b1100001;
      8'h6c: data = 9'b1100010;
      8'h6d: data = 9'b1100100;
      8'h6e: data = 9'b1100101;
      8'h6f: data = 9'b1100111;
      8'h70: data = 9'b1101000;
      8'h71: data = 9'b1101010;
      8'h72: data = 9'b1101011;
      8'h73: data = 9'b1101101;
      8'h74: data = 9'b1101110;
      8'h75: data = 9'b1110000;
      8'h76: data = 9'b1110001;
      8'h77: data = 9'b1110011;
      8'h78: data = 9'b1110100;
      8'h79: data = 9'b1110110;
      8'h7a: data = 9'b1110111;
      8'h7b: data = 9'b1111001;
      8'h7c: data = 9'b1111010;
      8'h7d: data = 9'b1111100;
      8'h7e: data = 9'b1111101;
      8'h7f: data = 9'b1111111;
      8'h80: data = 9'b10000000;
      8'h81: data = 9'b10000001;
      8'h82: data = 9'b10000011;
      8'h83: data = 9'b10000100;
      8'h84: data = 9'b10000110;
      8'h85: data = 9'b10000111;
      8'h86: data = 9'b10001001;
      8'h87: data = 9'b10001010;
      8'h88: data = 9'b10001100;
      8'h89: data = 9'b10001101;
      8'h8a: data = 9'b10001111;
      8'h8b: data = 9'b10010000;
      8'h8c: data = 9'b10010010;
      8'h8d: data = 9'b10010011;
      8'h8e: data = 9'b10010101;
      8'h8f: data = 9'b10010110;
      8'h90: data = 9'b10011000;
      8'h91: data = 9'b10011001;
      8'h92: data = 9'b10011011;
      8'h93: data = 9'b10011100;
      8'h94: data = 9'b10011110;
      8'h95: data = 9'b10011111;
      8'h96: data = 9'b10100001;
      8'h97: data = 9'b10100010;
      8'h98: data = 9'b10100100;
      8'h99: data = 9'b10100101;
      8'h9a: data = 9'b10100110;
      8'h9b: data = 9'b10101000;
      8'h9c: data = 9'b10101001;
      8'h9d: data = 9'b10101011;
      8'h9e: data = 9'b10101100;
      8'h9f: data = 9'b10101110;
      8'ha0: data = 9'b10101111;
      8'ha1: data = 9'b10110000;
      8'ha2: data = 9'b10110010;
      8'ha3: data = 9'b10110011;
      8'ha4: data = 9'b10110101;
      8'ha5: data = 9'b10110110;
      8'ha6: data = 9'b10110111;
      8'ha7: data = 9'b10111001;
      8'ha8: data = 9'b10111010;
      8'ha9: data = 9'b10111011;
      8'haa: data = 9'b10111101;
      8'hab: data = 9'b10111110;
      8'hac: data = 9'b10111111;
      8'had: data = 9'b11000001;
      8'hae: data = 9'b11000010;
      8'haf: data = 9'b11000011;
      8'hb0: data = 9'b11000101;
      8'hb1: data = 9'b11000110;
      8'hb2: data = 9'b11000111;
      8'hb3: data = 9'b11001000;
      8'hb4: data = 9'b11001010;
      8'hb5: data = 9'b11001011;
      8'hb6: data = 9'b11001100;
      8'hb7: data = 9'b11001101;
      8'hb8: data = 9'b11001111;
      8'hb9: data = 9'b11010000;
      8'hba: data = 9'b11010001;
      8'hbb: data = 9'b11010010;
      8'hbc: data = 9'b11010011;
      8'hbd: data = 9'b11010101;
      8'hbe: data = 9'b11010110;
      8'hbf: data = 9'b11010111;
      8'hc0: data = 9'b11011000;
      8'hc1: data = 9'b11011001;
      8'hc2: data = 9'b11011010;
      8'hc3: data = 9'b11011011;
      8'hc4: data = 9'b11011100;
      8'hc5: data = 9'b11011101;
      8'hc6: data = 9'b11011111;
      8'hc7: data = 9'b11100000;
      8'hc8: data = 9'b11100001;
      8'hc9: data = 9'b11100010;
      8'hca: data = 9'b11100011;
      8'hcb: data = 9'b11100100;
      8'hcc: data = 9'b11100101;
      8'hcd: data = 9'b11100110;
      8'hce: data = 9'b11100111;
      8'hcf: data = 9'b11100111;
      8'hd0: data = 9'b11101000;
      8'hd1: data = 9'b11101001;
      8'hd2: data = 9'b11101010;
      8'hd3: data = 9'b11101011;
      8'hd4: data = 9'b11101100;
      8'hd5: data = 9'b11101101;
      8'hd6: data = 9'b11101110;
      8'hd7: data = 9'b11101110;
      8'hd8: data = 9'b11101111;
      8'hd9: data = 9'b11110000;
      8'hda: data = 9'b11110001;
      8'hdb: data = 9'b11110010;
      8'hdc: data = 9'b11110010;
      8'hdd: data = 9'b11110011;
      8'hde: data = 9'b11110100;
      8'hdf: data = 9'b11110100;
      8'he0: data = 9'b11110101;
      8'he1: data = 9'b11110110;
      8'he2: data = 9'b11110110;
      8'he3: data = 9'b11110111;
      8'he4: data = 9'b11110111;
      8'he5: data = 9'b11111000;
      8'he6: data = 9'b11111001;
      8'he7: data = 9'b11111001;
      8'he8: data = 9'b11111010;
      8'he9: data = 9'b11111010;
      8'hea: data = 9'b11111011;
      8'heb: data = 9'b11111011;
      8'hec: data = 9'b11111100;
      8'hed: data = 9'b11111100;
      8'hee: data = 9'b11111100;
      8'hef: data = 9'b11111101;
      8'hf0: data = 9'b11111101;
      8'hf1: data = 9'b11111101;
      8'hf2: data = 9'b11111110;
      8'hf3: data = 9'b11111110;
      8'hf4: data = 9'b11111110;
      8'hf5: data = 9'b11111111;
      8'hf6: data = 9'b11111111;
      8'hf7: data = 9'b11111111;
      8'hf8: data = 9'b11111111;
      8'hf9: data = 9'b11111111;
      8'hfa: data = 9'b100000000;
      8'hfb: data = 9'b100000000;
      8'hfc: data = 9'b100000000;
      8'hfd: data = 9'b100000000;
      8'hfe: data = 9'b100000000;
      8'hff: data = 9'b100000000;
      default: data = 9'b0;
    endcase
            
endmodule // texture_path$unit$filter$weight$3$rom


module texture_path$unit$pair_alpha(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$pair_alpha


module texture_path$unit$pair_beta(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$pair_beta


module texture_path$unit$pair_words$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$pair_words$0


module texture_path$unit$pair_words$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$pair_words$1


module texture_path$unit$pair_words$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$pair_words$2


module texture_path$unit$pair_words$3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$pair_words$3


module texture_path$unit$pick$0(data0,data1,data2,data3,bank,word);
    
    // Module arguments
    input wire  [31:0] data0;
    input wire  [31:0] data1;
    input wire  [31:0] data2;
    input wire  [31:0] data3;
    input wire  [1:0] bank;
    output reg  [31:0] word;
    
    // Update code
    always @(*) begin
        word = data0;
        if (bank == 32'h1) begin
            word = data1;
        end
        if (bank == 32'h2) begin
            word = data2;
        end
        if (bank == 32'h3) begin
            word = data3;
        end
    end
    
endmodule // texture_path$unit$pick$0


module texture_path$unit$pick$1(data0,data1,data2,data3,bank,word);
    
    // Module arguments
    input wire  [31:0] data0;
    input wire  [31:0] data1;
    input wire  [31:0] data2;
    input wire  [31:0] data3;
    input wire  [1:0] bank;
    output reg  [31:0] word;
    
    // Update code
    always @(*) begin
        word = data0;
        if (bank == 32'h1) begin
            word = data1;
        end
        if (bank == 32'h2) begin
            word = data2;
        end
        if (bank == 32'h3) begin
            word = data3;
        end
    end
    
endmodule // texture_path$unit$pick$1


module texture_path$unit$pick$2(data0,data1,data2,data3,bank,word);
    
    // Module arguments
    input wire  [31:0] data0;
    input wire  [31:0] data1;
    input wire  [31:0] data2;
    input wire  [31:0] data3;
    input wire  [1:0] bank;
    output reg  [31:0] word;
    
    // Update code
    always @(*) begin
        word = data0;
        if (bank == 32'h1) begin
            word = data1;
        end
        if (bank == 32'h2) begin
            word = data2;
        end
        if (bank == 32'h3) begin
            word = data3;
        end
    end
    
endmodule // texture_path$unit$pick$2


module texture_path$unit$pick$3(data0,data1,data2,data3,bank,word);
    
    // Module arguments
    input wire  [31:0] data0;
    input wire  [31:0] data1;
    input wire  [31:0] data2;
    input wire  [31:0] data3;
    input wire  [1:0] bank;
    output reg  [31:0] word;
    
    // Update code
    always @(*) begin
        word = data0;
        if (bank == 32'h1) begin
            word = data1;
        end
        if (bank == 32'h2) begin
            word = data2;
        end
        if (bank == 32'h3) begin
            word = data3;
        end
    end
    
endmodule // texture_path$unit$pick$3


module texture_path$unit$r_base(d,q,clock);
    
    // Module arguments
    input wire  [25:0] d;
    output reg  [25:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 26'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$r_base


module texture_path$unit$r_env(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$r_env


module texture_path$unit$r_format(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$r_format


module texture_path$unit$r_gaussian(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$r_gaussian


module texture_path$unit$r_hs(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$r_hs


module texture_path$unit$r_levels(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$r_levels


module texture_path$unit$r_mag_linear(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$r_mag_linear


module texture_path$unit$r_min_linear(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$r_min_linear


module texture_path$unit$r_mip(d,q,clock);
    
    // Module arguments
    input wire  [1:0] d;
    output reg  [1:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 2'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$r_mip


module texture_path$unit$r_wrap_s(d,q,clock);
    
    // Module arguments
    input wire  [1:0] d;
    output reg  [1:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 2'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$r_wrap_s


module texture_path$unit$r_wrap_t(d,q,clock);
    
    // Module arguments
    input wire  [1:0] d;
    output reg  [1:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 2'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$r_wrap_t


module texture_path$unit$r_ws(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$r_ws


module texture_path$unit$rc(d,q,clock);
    
    // Module arguments
    input wire  [5:0] d;
    output reg  [5:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 6'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$rc


module texture_path$unit$rt(d,q,clock);
    
    // Module arguments
    input wire  [5:0] d;
    output reg  [5:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 6'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$rt


module texture_path$unit$second(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$second


module texture_path$unit$tag_ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [5:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [5:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[31:0] mem[63:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // texture_path$unit$tag_ram


module texture_path$unit$wp(d,q,clock);
    
    // Module arguments
    input wire  [5:0] d;
    output reg  [5:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 6'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$unit$wp


module texture_path$wp(d,q,clock);
    
    // Module arguments
    input wire  [5:0] d;
    output reg  [5:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 6'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_path$wp
