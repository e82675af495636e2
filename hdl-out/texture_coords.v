

module texture_coords(clock,en,inp_valid,inp_sq,inp_tq,inp_q,inp_dsq_x,inp_dsq_y,inp_dtq_x,inp_dtq_y,inp_dq_x,inp_dq_y,inp_ws,inp_hs,out_valid,out_s,out_t,out_lambda);
    
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
    texture_coords$recip recip(
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
    texture_coords$dl_sq$0 dl_sq$0(
        .d(dl_sq$0$d),
        .q(dl_sq$0$q),
        .clock(dl_sq$0$clock)
    );
    texture_coords$dl_sq$1 dl_sq$1(
        .d(dl_sq$1$d),
        .q(dl_sq$1$q),
        .clock(dl_sq$1$clock)
    );
    texture_coords$dl_sq$2 dl_sq$2(
        .d(dl_sq$2$d),
        .q(dl_sq$2$q),
        .clock(dl_sq$2$clock)
    );
    texture_coords$dl_sq$3 dl_sq$3(
        .d(dl_sq$3$d),
        .q(dl_sq$3$q),
        .clock(dl_sq$3$clock)
    );
    texture_coords$dl_sq$4 dl_sq$4(
        .d(dl_sq$4$d),
        .q(dl_sq$4$q),
        .clock(dl_sq$4$clock)
    );
    texture_coords$dl_sq$5 dl_sq$5(
        .d(dl_sq$5$d),
        .q(dl_sq$5$q),
        .clock(dl_sq$5$clock)
    );
    texture_coords$dl_sq$6 dl_sq$6(
        .d(dl_sq$6$d),
        .q(dl_sq$6$q),
        .clock(dl_sq$6$clock)
    );
    texture_coords$dl_sq$7 dl_sq$7(
        .d(dl_sq$7$d),
        .q(dl_sq$7$q),
        .clock(dl_sq$7$clock)
    );
    texture_coords$dl_sq$8 dl_sq$8(
        .d(dl_sq$8$d),
        .q(dl_sq$8$q),
        .clock(dl_sq$8$clock)
    );
    texture_coords$dl_sq$9 dl_sq$9(
        .d(dl_sq$9$d),
        .q(dl_sq$9$q),
        .clock(dl_sq$9$clock)
    );
    texture_coords$dl_sq$10 dl_sq$10(
        .d(dl_sq$10$d),
        .q(dl_sq$10$q),
        .clock(dl_sq$10$clock)
    );
    texture_coords$dl_sq$11 dl_sq$11(
        .d(dl_sq$11$d),
        .q(dl_sq$11$q),
        .clock(dl_sq$11$clock)
    );
    texture_coords$dl_sq$12 dl_sq$12(
        .d(dl_sq$12$d),
        .q(dl_sq$12$q),
        .clock(dl_sq$12$clock)
    );
    texture_coords$dl_tq$0 dl_tq$0(
        .d(dl_tq$0$d),
        .q(dl_tq$0$q),
        .clock(dl_tq$0$clock)
    );
    texture_coords$dl_tq$1 dl_tq$1(
        .d(dl_tq$1$d),
        .q(dl_tq$1$q),
        .clock(dl_tq$1$clock)
    );
    texture_coords$dl_tq$2 dl_tq$2(
        .d(dl_tq$2$d),
        .q(dl_tq$2$q),
        .clock(dl_tq$2$clock)
    );
    texture_coords$dl_tq$3 dl_tq$3(
        .d(dl_tq$3$d),
        .q(dl_tq$3$q),
        .clock(dl_tq$3$clock)
    );
    texture_coords$dl_tq$4 dl_tq$4(
        .d(dl_tq$4$d),
        .q(dl_tq$4$q),
        .clock(dl_tq$4$clock)
    );
    texture_coords$dl_tq$5 dl_tq$5(
        .d(dl_tq$5$d),
        .q(dl_tq$5$q),
        .clock(dl_tq$5$clock)
    );
    texture_coords$dl_tq$6 dl_tq$6(
        .d(dl_tq$6$d),
        .q(dl_tq$6$q),
        .clock(dl_tq$6$clock)
    );
    texture_coords$dl_tq$7 dl_tq$7(
        .d(dl_tq$7$d),
        .q(dl_tq$7$q),
        .clock(dl_tq$7$clock)
    );
    texture_coords$dl_tq$8 dl_tq$8(
        .d(dl_tq$8$d),
        .q(dl_tq$8$q),
        .clock(dl_tq$8$clock)
    );
    texture_coords$dl_tq$9 dl_tq$9(
        .d(dl_tq$9$d),
        .q(dl_tq$9$q),
        .clock(dl_tq$9$clock)
    );
    texture_coords$dl_tq$10 dl_tq$10(
        .d(dl_tq$10$d),
        .q(dl_tq$10$q),
        .clock(dl_tq$10$clock)
    );
    texture_coords$dl_tq$11 dl_tq$11(
        .d(dl_tq$11$d),
        .q(dl_tq$11$q),
        .clock(dl_tq$11$clock)
    );
    texture_coords$dl_tq$12 dl_tq$12(
        .d(dl_tq$12$d),
        .q(dl_tq$12$q),
        .clock(dl_tq$12$clock)
    );
    texture_coords$dl_dsq_x$0 dl_dsq_x$0(
        .d(dl_dsq_x$0$d),
        .q(dl_dsq_x$0$q),
        .clock(dl_dsq_x$0$clock)
    );
    texture_coords$dl_dsq_x$1 dl_dsq_x$1(
        .d(dl_dsq_x$1$d),
        .q(dl_dsq_x$1$q),
        .clock(dl_dsq_x$1$clock)
    );
    texture_coords$dl_dsq_x$2 dl_dsq_x$2(
        .d(dl_dsq_x$2$d),
        .q(dl_dsq_x$2$q),
        .clock(dl_dsq_x$2$clock)
    );
    texture_coords$dl_dsq_x$3 dl_dsq_x$3(
        .d(dl_dsq_x$3$d),
        .q(dl_dsq_x$3$q),
        .clock(dl_dsq_x$3$clock)
    );
    texture_coords$dl_dsq_x$4 dl_dsq_x$4(
        .d(dl_dsq_x$4$d),
        .q(dl_dsq_x$4$q),
        .clock(dl_dsq_x$4$clock)
    );
    texture_coords$dl_dsq_x$5 dl_dsq_x$5(
        .d(dl_dsq_x$5$d),
        .q(dl_dsq_x$5$q),
        .clock(dl_dsq_x$5$clock)
    );
    texture_coords$dl_dsq_x$6 dl_dsq_x$6(
        .d(dl_dsq_x$6$d),
        .q(dl_dsq_x$6$q),
        .clock(dl_dsq_x$6$clock)
    );
    texture_coords$dl_dsq_x$7 dl_dsq_x$7(
        .d(dl_dsq_x$7$d),
        .q(dl_dsq_x$7$q),
        .clock(dl_dsq_x$7$clock)
    );
    texture_coords$dl_dsq_x$8 dl_dsq_x$8(
        .d(dl_dsq_x$8$d),
        .q(dl_dsq_x$8$q),
        .clock(dl_dsq_x$8$clock)
    );
    texture_coords$dl_dsq_x$9 dl_dsq_x$9(
        .d(dl_dsq_x$9$d),
        .q(dl_dsq_x$9$q),
        .clock(dl_dsq_x$9$clock)
    );
    texture_coords$dl_dsq_x$10 dl_dsq_x$10(
        .d(dl_dsq_x$10$d),
        .q(dl_dsq_x$10$q),
        .clock(dl_dsq_x$10$clock)
    );
    texture_coords$dl_dsq_x$11 dl_dsq_x$11(
        .d(dl_dsq_x$11$d),
        .q(dl_dsq_x$11$q),
        .clock(dl_dsq_x$11$clock)
    );
    texture_coords$dl_dsq_x$12 dl_dsq_x$12(
        .d(dl_dsq_x$12$d),
        .q(dl_dsq_x$12$q),
        .clock(dl_dsq_x$12$clock)
    );
    texture_coords$dl_dsq_y$0 dl_dsq_y$0(
        .d(dl_dsq_y$0$d),
        .q(dl_dsq_y$0$q),
        .clock(dl_dsq_y$0$clock)
    );
    texture_coords$dl_dsq_y$1 dl_dsq_y$1(
        .d(dl_dsq_y$1$d),
        .q(dl_dsq_y$1$q),
        .clock(dl_dsq_y$1$clock)
    );
    texture_coords$dl_dsq_y$2 dl_dsq_y$2(
        .d(dl_dsq_y$2$d),
        .q(dl_dsq_y$2$q),
        .clock(dl_dsq_y$2$clock)
    );
    texture_coords$dl_dsq_y$3 dl_dsq_y$3(
        .d(dl_dsq_y$3$d),
        .q(dl_dsq_y$3$q),
        .clock(dl_dsq_y$3$clock)
    );
    texture_coords$dl_dsq_y$4 dl_dsq_y$4(
        .d(dl_dsq_y$4$d),
        .q(dl_dsq_y$4$q),
        .clock(dl_dsq_y$4$clock)
    );
    texture_coords$dl_dsq_y$5 dl_dsq_y$5(
        .d(dl_dsq_y$5$d),
        .q(dl_dsq_y$5$q),
        .clock(dl_dsq_y$5$clock)
    );
    texture_coords$dl_dsq_y$6 dl_dsq_y$6(
        .d(dl_dsq_y$6$d),
        .q(dl_dsq_y$6$q),
        .clock(dl_dsq_y$6$clock)
    );
    texture_coords$dl_dsq_y$7 dl_dsq_y$7(
        .d(dl_dsq_y$7$d),
        .q(dl_dsq_y$7$q),
        .clock(dl_dsq_y$7$clock)
    );
    texture_coords$dl_dsq_y$8 dl_dsq_y$8(
        .d(dl_dsq_y$8$d),
        .q(dl_dsq_y$8$q),
        .clock(dl_dsq_y$8$clock)
    );
    texture_coords$dl_dsq_y$9 dl_dsq_y$9(
        .d(dl_dsq_y$9$d),
        .q(dl_dsq_y$9$q),
        .clock(dl_dsq_y$9$clock)
    );
    texture_coords$dl_dsq_y$10 dl_dsq_y$10(
        .d(dl_dsq_y$10$d),
        .q(dl_dsq_y$10$q),
        .clock(dl_dsq_y$10$clock)
    );
    texture_coords$dl_dsq_y$11 dl_dsq_y$11(
        .d(dl_dsq_y$11$d),
        .q(dl_dsq_y$11$q),
        .clock(dl_dsq_y$11$clock)
    );
    texture_coords$dl_dsq_y$12 dl_dsq_y$12(
        .d(dl_dsq_y$12$d),
        .q(dl_dsq_y$12$q),
        .clock(dl_dsq_y$12$clock)
    );
    texture_coords$dl_dtq_x$0 dl_dtq_x$0(
        .d(dl_dtq_x$0$d),
        .q(dl_dtq_x$0$q),
        .clock(dl_dtq_x$0$clock)
    );
    texture_coords$dl_dtq_x$1 dl_dtq_x$1(
        .d(dl_dtq_x$1$d),
        .q(dl_dtq_x$1$q),
        .clock(dl_dtq_x$1$clock)
    );
    texture_coords$dl_dtq_x$2 dl_dtq_x$2(
        .d(dl_dtq_x$2$d),
        .q(dl_dtq_x$2$q),
        .clock(dl_dtq_x$2$clock)
    );
    texture_coords$dl_dtq_x$3 dl_dtq_x$3(
        .d(dl_dtq_x$3$d),
        .q(dl_dtq_x$3$q),
        .clock(dl_dtq_x$3$clock)
    );
    texture_coords$dl_dtq_x$4 dl_dtq_x$4(
        .d(dl_dtq_x$4$d),
        .q(dl_dtq_x$4$q),
        .clock(dl_dtq_x$4$clock)
    );
    texture_coords$dl_dtq_x$5 dl_dtq_x$5(
        .d(dl_dtq_x$5$d),
        .q(dl_dtq_x$5$q),
        .clock(dl_dtq_x$5$clock)
    );
    texture_coords$dl_dtq_x$6 dl_dtq_x$6(
        .d(dl_dtq_x$6$d),
        .q(dl_dtq_x$6$q),
        .clock(dl_dtq_x$6$clock)
    );
    texture_coords$dl_dtq_x$7 dl_dtq_x$7(
        .d(dl_dtq_x$7$d),
        .q(dl_dtq_x$7$q),
        .clock(dl_dtq_x$7$clock)
    );
    texture_coords$dl_dtq_x$8 dl_dtq_x$8(
        .d(dl_dtq_x$8$d),
        .q(dl_dtq_x$8$q),
        .clock(dl_dtq_x$8$clock)
    );
    texture_coords$dl_dtq_x$9 dl_dtq_x$9(
        .d(dl_dtq_x$9$d),
        .q(dl_dtq_x$9$q),
        .clock(dl_dtq_x$9$clock)
    );
    texture_coords$dl_dtq_x$10 dl_dtq_x$10(
        .d(dl_dtq_x$10$d),
        .q(dl_dtq_x$10$q),
        .clock(dl_dtq_x$10$clock)
    );
    texture_coords$dl_dtq_x$11 dl_dtq_x$11(
        .d(dl_dtq_x$11$d),
        .q(dl_dtq_x$11$q),
        .clock(dl_dtq_x$11$clock)
    );
    texture_coords$dl_dtq_x$12 dl_dtq_x$12(
        .d(dl_dtq_x$12$d),
        .q(dl_dtq_x$12$q),
        .clock(dl_dtq_x$12$clock)
    );
    texture_coords$dl_dtq_y$0 dl_dtq_y$0(
        .d(dl_dtq_y$0$d),
        .q(dl_dtq_y$0$q),
        .clock(dl_dtq_y$0$clock)
    );
    texture_coords$dl_dtq_y$1 dl_dtq_y$1(
        .d(dl_dtq_y$1$d),
        .q(dl_dtq_y$1$q),
        .clock(dl_dtq_y$1$clock)
    );
    texture_coords$dl_dtq_y$2 dl_dtq_y$2(
        .d(dl_dtq_y$2$d),
        .q(dl_dtq_y$2$q),
        .clock(dl_dtq_y$2$clock)
    );
    texture_coords$dl_dtq_y$3 dl_dtq_y$3(
        .d(dl_dtq_y$3$d),
        .q(dl_dtq_y$3$q),
        .clock(dl_dtq_y$3$clock)
    );
    texture_coords$dl_dtq_y$4 dl_dtq_y$4(
        .d(dl_dtq_y$4$d),
        .q(dl_dtq_y$4$q),
        .clock(dl_dtq_y$4$clock)
    );
    texture_coords$dl_dtq_y$5 dl_dtq_y$5(
        .d(dl_dtq_y$5$d),
        .q(dl_dtq_y$5$q),
        .clock(dl_dtq_y$5$clock)
    );
    texture_coords$dl_dtq_y$6 dl_dtq_y$6(
        .d(dl_dtq_y$6$d),
        .q(dl_dtq_y$6$q),
        .clock(dl_dtq_y$6$clock)
    );
    texture_coords$dl_dtq_y$7 dl_dtq_y$7(
        .d(dl_dtq_y$7$d),
        .q(dl_dtq_y$7$q),
        .clock(dl_dtq_y$7$clock)
    );
    texture_coords$dl_dtq_y$8 dl_dtq_y$8(
        .d(dl_dtq_y$8$d),
        .q(dl_dtq_y$8$q),
        .clock(dl_dtq_y$8$clock)
    );
    texture_coords$dl_dtq_y$9 dl_dtq_y$9(
        .d(dl_dtq_y$9$d),
        .q(dl_dtq_y$9$q),
        .clock(dl_dtq_y$9$clock)
    );
    texture_coords$dl_dtq_y$10 dl_dtq_y$10(
        .d(dl_dtq_y$10$d),
        .q(dl_dtq_y$10$q),
        .clock(dl_dtq_y$10$clock)
    );
    texture_coords$dl_dtq_y$11 dl_dtq_y$11(
        .d(dl_dtq_y$11$d),
        .q(dl_dtq_y$11$q),
        .clock(dl_dtq_y$11$clock)
    );
    texture_coords$dl_dtq_y$12 dl_dtq_y$12(
        .d(dl_dtq_y$12$d),
        .q(dl_dtq_y$12$q),
        .clock(dl_dtq_y$12$clock)
    );
    texture_coords$dl_dq_x$0 dl_dq_x$0(
        .d(dl_dq_x$0$d),
        .q(dl_dq_x$0$q),
        .clock(dl_dq_x$0$clock)
    );
    texture_coords$dl_dq_x$1 dl_dq_x$1(
        .d(dl_dq_x$1$d),
        .q(dl_dq_x$1$q),
        .clock(dl_dq_x$1$clock)
    );
    texture_coords$dl_dq_x$2 dl_dq_x$2(
        .d(dl_dq_x$2$d),
        .q(dl_dq_x$2$q),
        .clock(dl_dq_x$2$clock)
    );
    texture_coords$dl_dq_x$3 dl_dq_x$3(
        .d(dl_dq_x$3$d),
        .q(dl_dq_x$3$q),
        .clock(dl_dq_x$3$clock)
    );
    texture_coords$dl_dq_x$4 dl_dq_x$4(
        .d(dl_dq_x$4$d),
        .q(dl_dq_x$4$q),
        .clock(dl_dq_x$4$clock)
    );
    texture_coords$dl_dq_x$5 dl_dq_x$5(
        .d(dl_dq_x$5$d),
        .q(dl_dq_x$5$q),
        .clock(dl_dq_x$5$clock)
    );
    texture_coords$dl_dq_x$6 dl_dq_x$6(
        .d(dl_dq_x$6$d),
        .q(dl_dq_x$6$q),
        .clock(dl_dq_x$6$clock)
    );
    texture_coords$dl_dq_x$7 dl_dq_x$7(
        .d(dl_dq_x$7$d),
        .q(dl_dq_x$7$q),
        .clock(dl_dq_x$7$clock)
    );
    texture_coords$dl_dq_x$8 dl_dq_x$8(
        .d(dl_dq_x$8$d),
        .q(dl_dq_x$8$q),
        .clock(dl_dq_x$8$clock)
    );
    texture_coords$dl_dq_x$9 dl_dq_x$9(
        .d(dl_dq_x$9$d),
        .q(dl_dq_x$9$q),
        .clock(dl_dq_x$9$clock)
    );
    texture_coords$dl_dq_x$10 dl_dq_x$10(
        .d(dl_dq_x$10$d),
        .q(dl_dq_x$10$q),
        .clock(dl_dq_x$10$clock)
    );
    texture_coords$dl_dq_x$11 dl_dq_x$11(
        .d(dl_dq_x$11$d),
        .q(dl_dq_x$11$q),
        .clock(dl_dq_x$11$clock)
    );
    texture_coords$dl_dq_x$12 dl_dq_x$12(
        .d(dl_dq_x$12$d),
        .q(dl_dq_x$12$q),
        .clock(dl_dq_x$12$clock)
    );
    texture_coords$dl_dq_y$0 dl_dq_y$0(
        .d(dl_dq_y$0$d),
        .q(dl_dq_y$0$q),
        .clock(dl_dq_y$0$clock)
    );
    texture_coords$dl_dq_y$1 dl_dq_y$1(
        .d(dl_dq_y$1$d),
        .q(dl_dq_y$1$q),
        .clock(dl_dq_y$1$clock)
    );
    texture_coords$dl_dq_y$2 dl_dq_y$2(
        .d(dl_dq_y$2$d),
        .q(dl_dq_y$2$q),
        .clock(dl_dq_y$2$clock)
    );
    texture_coords$dl_dq_y$3 dl_dq_y$3(
        .d(dl_dq_y$3$d),
        .q(dl_dq_y$3$q),
        .clock(dl_dq_y$3$clock)
    );
    texture_coords$dl_dq_y$4 dl_dq_y$4(
        .d(dl_dq_y$4$d),
        .q(dl_dq_y$4$q),
        .clock(dl_dq_y$4$clock)
    );
    texture_coords$dl_dq_y$5 dl_dq_y$5(
        .d(dl_dq_y$5$d),
        .q(dl_dq_y$5$q),
        .clock(dl_dq_y$5$clock)
    );
    texture_coords$dl_dq_y$6 dl_dq_y$6(
        .d(dl_dq_y$6$d),
        .q(dl_dq_y$6$q),
        .clock(dl_dq_y$6$clock)
    );
    texture_coords$dl_dq_y$7 dl_dq_y$7(
        .d(dl_dq_y$7$d),
        .q(dl_dq_y$7$q),
        .clock(dl_dq_y$7$clock)
    );
    texture_coords$dl_dq_y$8 dl_dq_y$8(
        .d(dl_dq_y$8$d),
        .q(dl_dq_y$8$q),
        .clock(dl_dq_y$8$clock)
    );
    texture_coords$dl_dq_y$9 dl_dq_y$9(
        .d(dl_dq_y$9$d),
        .q(dl_dq_y$9$q),
        .clock(dl_dq_y$9$clock)
    );
    texture_coords$dl_dq_y$10 dl_dq_y$10(
        .d(dl_dq_y$10$d),
        .q(dl_dq_y$10$q),
        .clock(dl_dq_y$10$clock)
    );
    texture_coords$dl_dq_y$11 dl_dq_y$11(
        .d(dl_dq_y$11$d),
        .q(dl_dq_y$11$q),
        .clock(dl_dq_y$11$clock)
    );
    texture_coords$dl_dq_y$12 dl_dq_y$12(
        .d(dl_dq_y$12$d),
        .q(dl_dq_y$12$q),
        .clock(dl_dq_y$12$clock)
    );
    texture_coords$dl_lz$0 dl_lz$0(
        .d(dl_lz$0$d),
        .q(dl_lz$0$q),
        .clock(dl_lz$0$clock)
    );
    texture_coords$dl_lz$1 dl_lz$1(
        .d(dl_lz$1$d),
        .q(dl_lz$1$q),
        .clock(dl_lz$1$clock)
    );
    texture_coords$dl_lz$2 dl_lz$2(
        .d(dl_lz$2$d),
        .q(dl_lz$2$q),
        .clock(dl_lz$2$clock)
    );
    texture_coords$dl_lz$3 dl_lz$3(
        .d(dl_lz$3$d),
        .q(dl_lz$3$q),
        .clock(dl_lz$3$clock)
    );
    texture_coords$dl_lz$4 dl_lz$4(
        .d(dl_lz$4$d),
        .q(dl_lz$4$q),
        .clock(dl_lz$4$clock)
    );
    texture_coords$dl_lz$5 dl_lz$5(
        .d(dl_lz$5$d),
        .q(dl_lz$5$q),
        .clock(dl_lz$5$clock)
    );
    texture_coords$dl_lz$6 dl_lz$6(
        .d(dl_lz$6$d),
        .q(dl_lz$6$q),
        .clock(dl_lz$6$clock)
    );
    texture_coords$dl_lz$7 dl_lz$7(
        .d(dl_lz$7$d),
        .q(dl_lz$7$q),
        .clock(dl_lz$7$clock)
    );
    texture_coords$dl_lz$8 dl_lz$8(
        .d(dl_lz$8$d),
        .q(dl_lz$8$q),
        .clock(dl_lz$8$clock)
    );
    texture_coords$dl_lz$9 dl_lz$9(
        .d(dl_lz$9$d),
        .q(dl_lz$9$q),
        .clock(dl_lz$9$clock)
    );
    texture_coords$dl_lz$10 dl_lz$10(
        .d(dl_lz$10$d),
        .q(dl_lz$10$q),
        .clock(dl_lz$10$clock)
    );
    texture_coords$dl_lz$11 dl_lz$11(
        .d(dl_lz$11$d),
        .q(dl_lz$11$q),
        .clock(dl_lz$11$clock)
    );
    texture_coords$dl_lz$12 dl_lz$12(
        .d(dl_lz$12$d),
        .q(dl_lz$12$q),
        .clock(dl_lz$12$clock)
    );
    texture_coords$dl_ws$0 dl_ws$0(
        .d(dl_ws$0$d),
        .q(dl_ws$0$q),
        .clock(dl_ws$0$clock)
    );
    texture_coords$dl_ws$1 dl_ws$1(
        .d(dl_ws$1$d),
        .q(dl_ws$1$q),
        .clock(dl_ws$1$clock)
    );
    texture_coords$dl_ws$2 dl_ws$2(
        .d(dl_ws$2$d),
        .q(dl_ws$2$q),
        .clock(dl_ws$2$clock)
    );
    texture_coords$dl_ws$3 dl_ws$3(
        .d(dl_ws$3$d),
        .q(dl_ws$3$q),
        .clock(dl_ws$3$clock)
    );
    texture_coords$dl_ws$4 dl_ws$4(
        .d(dl_ws$4$d),
        .q(dl_ws$4$q),
        .clock(dl_ws$4$clock)
    );
    texture_coords$dl_ws$5 dl_ws$5(
        .d(dl_ws$5$d),
        .q(dl_ws$5$q),
        .clock(dl_ws$5$clock)
    );
    texture_coords$dl_ws$6 dl_ws$6(
        .d(dl_ws$6$d),
        .q(dl_ws$6$q),
        .clock(dl_ws$6$clock)
    );
    texture_coords$dl_ws$7 dl_ws$7(
        .d(dl_ws$7$d),
        .q(dl_ws$7$q),
        .clock(dl_ws$7$clock)
    );
    texture_coords$dl_ws$8 dl_ws$8(
        .d(dl_ws$8$d),
        .q(dl_ws$8$q),
        .clock(dl_ws$8$clock)
    );
    texture_coords$dl_ws$9 dl_ws$9(
        .d(dl_ws$9$d),
        .q(dl_ws$9$q),
        .clock(dl_ws$9$clock)
    );
    texture_coords$dl_ws$10 dl_ws$10(
        .d(dl_ws$10$d),
        .q(dl_ws$10$q),
        .clock(dl_ws$10$clock)
    );
    texture_coords$dl_ws$11 dl_ws$11(
        .d(dl_ws$11$d),
        .q(dl_ws$11$q),
        .clock(dl_ws$11$clock)
    );
    texture_coords$dl_ws$12 dl_ws$12(
        .d(dl_ws$12$d),
        .q(dl_ws$12$q),
        .clock(dl_ws$12$clock)
    );
    texture_coords$dl_hs$0 dl_hs$0(
        .d(dl_hs$0$d),
        .q(dl_hs$0$q),
        .clock(dl_hs$0$clock)
    );
    texture_coords$dl_hs$1 dl_hs$1(
        .d(dl_hs$1$d),
        .q(dl_hs$1$q),
        .clock(dl_hs$1$clock)
    );
    texture_coords$dl_hs$2 dl_hs$2(
        .d(dl_hs$2$d),
        .q(dl_hs$2$q),
        .clock(dl_hs$2$clock)
    );
    texture_coords$dl_hs$3 dl_hs$3(
        .d(dl_hs$3$d),
        .q(dl_hs$3$q),
        .clock(dl_hs$3$clock)
    );
    texture_coords$dl_hs$4 dl_hs$4(
        .d(dl_hs$4$d),
        .q(dl_hs$4$q),
        .clock(dl_hs$4$clock)
    );
    texture_coords$dl_hs$5 dl_hs$5(
        .d(dl_hs$5$d),
        .q(dl_hs$5$q),
        .clock(dl_hs$5$clock)
    );
    texture_coords$dl_hs$6 dl_hs$6(
        .d(dl_hs$6$d),
        .q(dl_hs$6$q),
        .clock(dl_hs$6$clock)
    );
    texture_coords$dl_hs$7 dl_hs$7(
        .d(dl_hs$7$d),
        .q(dl_hs$7$q),
        .clock(dl_hs$7$clock)
    );
    texture_coords$dl_hs$8 dl_hs$8(
        .d(dl_hs$8$d),
        .q(dl_hs$8$q),
        .clock(dl_hs$8$clock)
    );
    texture_coords$dl_hs$9 dl_hs$9(
        .d(dl_hs$9$d),
        .q(dl_hs$9$q),
        .clock(dl_hs$9$clock)
    );
    texture_coords$dl_hs$10 dl_hs$10(
        .d(dl_hs$10$d),
        .q(dl_hs$10$q),
        .clock(dl_hs$10$clock)
    );
    texture_coords$dl_hs$11 dl_hs$11(
        .d(dl_hs$11$d),
        .q(dl_hs$11$q),
        .clock(dl_hs$11$clock)
    );
    texture_coords$dl_hs$12 dl_hs$12(
        .d(dl_hs$12$d),
        .q(dl_hs$12$q),
        .clock(dl_hs$12$clock)
    );
    texture_coords$mul_s mul_s(
        .a(mul_s$a),
        .b(mul_s$b),
        .p(mul_s$p)
    );
    texture_coords$mul_t mul_t(
        .a(mul_t$a),
        .b(mul_t$b),
        .p(mul_t$p)
    );
    texture_coords$b1_valid b1_valid(
        .d(b1_valid$d),
        .q(b1_valid$q),
        .clock(b1_valid$clock)
    );
    texture_coords$b1_p$0 b1_p$0(
        .d(b1_p$0$d),
        .q(b1_p$0$q),
        .clock(b1_p$0$clock)
    );
    texture_coords$b1_p$1 b1_p$1(
        .d(b1_p$1$d),
        .q(b1_p$1$q),
        .clock(b1_p$1$clock)
    );
    texture_coords$b1_sh b1_sh(
        .d(b1_sh$d),
        .q(b1_sh$q),
        .clock(b1_sh$clock)
    );
    texture_coords$b1_dxq$0 b1_dxq$0(
        .d(b1_dxq$0$d),
        .q(b1_dxq$0$q),
        .clock(b1_dxq$0$clock)
    );
    texture_coords$b1_dxq$1 b1_dxq$1(
        .d(b1_dxq$1$d),
        .q(b1_dxq$1$q),
        .clock(b1_dxq$1$clock)
    );
    texture_coords$b1_dxq$2 b1_dxq$2(
        .d(b1_dxq$2$d),
        .q(b1_dxq$2$q),
        .clock(b1_dxq$2$clock)
    );
    texture_coords$b1_dxq$3 b1_dxq$3(
        .d(b1_dxq$3$d),
        .q(b1_dxq$3$q),
        .clock(b1_dxq$3$clock)
    );
    texture_coords$b1_dq$0 b1_dq$0(
        .d(b1_dq$0$d),
        .q(b1_dq$0$q),
        .clock(b1_dq$0$clock)
    );
    texture_coords$b1_dq$1 b1_dq$1(
        .d(b1_dq$1$d),
        .q(b1_dq$1$q),
        .clock(b1_dq$1$clock)
    );
    texture_coords$b1_lz b1_lz(
        .d(b1_lz$d),
        .q(b1_lz$q),
        .clock(b1_lz$clock)
    );
    texture_coords$b1_ws b1_ws(
        .d(b1_ws$d),
        .q(b1_ws$q),
        .clock(b1_ws$clock)
    );
    texture_coords$b1_hs b1_hs(
        .d(b1_hs$d),
        .q(b1_hs$q),
        .clock(b1_hs$clock)
    );
    texture_coords$b1_r b1_r(
        .d(b1_r$d),
        .q(b1_r$q),
        .clock(b1_r$clock)
    );
    texture_coords$b_valid b_valid(
        .d(b_valid$d),
        .q(b_valid$q),
        .clock(b_valid$clock)
    );
    texture_coords$b_st$0 b_st$0(
        .d(b_st$0$d),
        .q(b_st$0$q),
        .clock(b_st$0$clock)
    );
    texture_coords$b_st$1 b_st$1(
        .d(b_st$1$d),
        .q(b_st$1$q),
        .clock(b_st$1$clock)
    );
    texture_coords$b_dxq$0 b_dxq$0(
        .d(b_dxq$0$d),
        .q(b_dxq$0$q),
        .clock(b_dxq$0$clock)
    );
    texture_coords$b_dxq$1 b_dxq$1(
        .d(b_dxq$1$d),
        .q(b_dxq$1$q),
        .clock(b_dxq$1$clock)
    );
    texture_coords$b_dxq$2 b_dxq$2(
        .d(b_dxq$2$d),
        .q(b_dxq$2$q),
        .clock(b_dxq$2$clock)
    );
    texture_coords$b_dxq$3 b_dxq$3(
        .d(b_dxq$3$d),
        .q(b_dxq$3$q),
        .clock(b_dxq$3$clock)
    );
    texture_coords$b_dq$0 b_dq$0(
        .d(b_dq$0$d),
        .q(b_dq$0$q),
        .clock(b_dq$0$clock)
    );
    texture_coords$b_dq$1 b_dq$1(
        .d(b_dq$1$d),
        .q(b_dq$1$q),
        .clock(b_dq$1$clock)
    );
    texture_coords$b_lz b_lz(
        .d(b_lz$d),
        .q(b_lz$q),
        .clock(b_lz$clock)
    );
    texture_coords$b_ws b_ws(
        .d(b_ws$d),
        .q(b_ws$q),
        .clock(b_ws$clock)
    );
    texture_coords$b_hs b_hs(
        .d(b_hs$d),
        .q(b_hs$q),
        .clock(b_hs$clock)
    );
    texture_coords$b_r b_r(
        .d(b_r$d),
        .q(b_r$q),
        .clock(b_r$clock)
    );
    texture_coords$mul_g$0 mul_g$0(
        .a(mul_g$0$a),
        .b(mul_g$0$b),
        .p(mul_g$0$p)
    );
    texture_coords$mul_g$1 mul_g$1(
        .a(mul_g$1$a),
        .b(mul_g$1$b),
        .p(mul_g$1$p)
    );
    texture_coords$mul_g$2 mul_g$2(
        .a(mul_g$2$a),
        .b(mul_g$2$b),
        .p(mul_g$2$p)
    );
    texture_coords$mul_g$3 mul_g$3(
        .a(mul_g$3$a),
        .b(mul_g$3$b),
        .p(mul_g$3$p)
    );
    texture_coords$c1_valid c1_valid(
        .d(c1_valid$d),
        .q(c1_valid$q),
        .clock(c1_valid$clock)
    );
    texture_coords$c1_st$0 c1_st$0(
        .d(c1_st$0$d),
        .q(c1_st$0$q),
        .clock(c1_st$0$clock)
    );
    texture_coords$c1_st$1 c1_st$1(
        .d(c1_st$1$d),
        .q(c1_st$1$q),
        .clock(c1_st$1$clock)
    );
    texture_coords$c1_p$0 c1_p$0(
        .d(c1_p$0$d),
        .q(c1_p$0$q),
        .clock(c1_p$0$clock)
    );
    texture_coords$c1_p$1 c1_p$1(
        .d(c1_p$1$d),
        .q(c1_p$1$q),
        .clock(c1_p$1$clock)
    );
    texture_coords$c1_p$2 c1_p$2(
        .d(c1_p$2$d),
        .q(c1_p$2$q),
        .clock(c1_p$2$clock)
    );
    texture_coords$c1_p$3 c1_p$3(
        .d(c1_p$3$d),
        .q(c1_p$3$q),
        .clock(c1_p$3$clock)
    );
    texture_coords$c1_dxq$0 c1_dxq$0(
        .d(c1_dxq$0$d),
        .q(c1_dxq$0$q),
        .clock(c1_dxq$0$clock)
    );
    texture_coords$c1_dxq$1 c1_dxq$1(
        .d(c1_dxq$1$d),
        .q(c1_dxq$1$q),
        .clock(c1_dxq$1$clock)
    );
    texture_coords$c1_dxq$2 c1_dxq$2(
        .d(c1_dxq$2$d),
        .q(c1_dxq$2$q),
        .clock(c1_dxq$2$clock)
    );
    texture_coords$c1_dxq$3 c1_dxq$3(
        .d(c1_dxq$3$d),
        .q(c1_dxq$3$q),
        .clock(c1_dxq$3$clock)
    );
    texture_coords$c1_lz c1_lz(
        .d(c1_lz$d),
        .q(c1_lz$q),
        .clock(c1_lz$clock)
    );
    texture_coords$c1_ws c1_ws(
        .d(c1_ws$d),
        .q(c1_ws$q),
        .clock(c1_ws$clock)
    );
    texture_coords$c1_hs c1_hs(
        .d(c1_hs$d),
        .q(c1_hs$q),
        .clock(c1_hs$clock)
    );
    texture_coords$c1_r c1_r(
        .d(c1_r$d),
        .q(c1_r$q),
        .clock(c1_r$clock)
    );
    texture_coords$num$0 num$0(
        .dxq(num$0$dxq),
        .p(num$0$p),
        .size_log2(num$0$size_log2),
        .u(num$0$u)
    );
    texture_coords$num$1 num$1(
        .dxq(num$1$dxq),
        .p(num$1$p),
        .size_log2(num$1$size_log2),
        .u(num$1$u)
    );
    texture_coords$num$2 num$2(
        .dxq(num$2$dxq),
        .p(num$2$p),
        .size_log2(num$2$size_log2),
        .u(num$2$u)
    );
    texture_coords$num$3 num$3(
        .dxq(num$3$dxq),
        .p(num$3$p),
        .size_log2(num$3$size_log2),
        .u(num$3$u)
    );
    texture_coords$c_valid c_valid(
        .d(c_valid$d),
        .q(c_valid$q),
        .clock(c_valid$clock)
    );
    texture_coords$c_st$0 c_st$0(
        .d(c_st$0$d),
        .q(c_st$0$q),
        .clock(c_st$0$clock)
    );
    texture_coords$c_st$1 c_st$1(
        .d(c_st$1$d),
        .q(c_st$1$q),
        .clock(c_st$1$clock)
    );
    texture_coords$c_u$0 c_u$0(
        .d(c_u$0$d),
        .q(c_u$0$q),
        .clock(c_u$0$clock)
    );
    texture_coords$c_u$1 c_u$1(
        .d(c_u$1$d),
        .q(c_u$1$q),
        .clock(c_u$1$clock)
    );
    texture_coords$c_u$2 c_u$2(
        .d(c_u$2$d),
        .q(c_u$2$q),
        .clock(c_u$2$clock)
    );
    texture_coords$c_u$3 c_u$3(
        .d(c_u$3$d),
        .q(c_u$3$q),
        .clock(c_u$3$clock)
    );
    texture_coords$c_lz c_lz(
        .d(c_lz$d),
        .q(c_lz$q),
        .clock(c_lz$clock)
    );
    texture_coords$c_r c_r(
        .d(c_r$d),
        .q(c_r$q),
        .clock(c_r$clock)
    );
    texture_coords$mul_sq$0 mul_sq$0(
        .a(mul_sq$0$a),
        .b(mul_sq$0$b),
        .p(mul_sq$0$p)
    );
    texture_coords$mul_sq$1 mul_sq$1(
        .a(mul_sq$1$a),
        .b(mul_sq$1$b),
        .p(mul_sq$1$p)
    );
    texture_coords$mul_sq$2 mul_sq$2(
        .a(mul_sq$2$a),
        .b(mul_sq$2$b),
        .p(mul_sq$2$p)
    );
    texture_coords$mul_sq$3 mul_sq$3(
        .a(mul_sq$3$a),
        .b(mul_sq$3$b),
        .p(mul_sq$3$p)
    );
    texture_coords$d_valid d_valid(
        .d(d_valid$d),
        .q(d_valid$q),
        .clock(d_valid$clock)
    );
    texture_coords$d_st$0 d_st$0(
        .d(d_st$0$d),
        .q(d_st$0$q),
        .clock(d_st$0$clock)
    );
    texture_coords$d_st$1 d_st$1(
        .d(d_st$1$d),
        .q(d_st$1$q),
        .clock(d_st$1$clock)
    );
    texture_coords$d_m d_m(
        .d(d_m$d),
        .q(d_m$q),
        .clock(d_m$clock)
    );
    texture_coords$d_lz d_lz(
        .d(d_lz$d),
        .q(d_lz$q),
        .clock(d_lz$clock)
    );
    texture_coords$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    texture_coords$e1_valid e1_valid(
        .d(e1_valid$d),
        .q(e1_valid$q),
        .clock(e1_valid$clock)
    );
    texture_coords$e1_zero e1_zero(
        .d(e1_zero$d),
        .q(e1_zero$q),
        .clock(e1_zero$clock)
    );
    texture_coords$e1_st$0 e1_st$0(
        .d(e1_st$0$d),
        .q(e1_st$0$q),
        .clock(e1_st$0$clock)
    );
    texture_coords$e1_st$1 e1_st$1(
        .d(e1_st$1$d),
        .q(e1_st$1$q),
        .clock(e1_st$1$clock)
    );
    texture_coords$e1_p$0 e1_p$0(
        .d(e1_p$0$d),
        .q(e1_p$0$q),
        .clock(e1_p$0$clock)
    );
    texture_coords$e1_p$1 e1_p$1(
        .d(e1_p$1$d),
        .q(e1_p$1$q),
        .clock(e1_p$1$clock)
    );
    texture_coords$e1_idx$0 e1_idx$0(
        .d(e1_idx$0$d),
        .q(e1_idx$0$q),
        .clock(e1_idx$0$clock)
    );
    texture_coords$e1_idx$1 e1_idx$1(
        .d(e1_idx$1$d),
        .q(e1_idx$1$q),
        .clock(e1_idx$1$clock)
    );
    texture_coords$e1_lz e1_lz(
        .d(e1_lz$d),
        .q(e1_lz$q),
        .clock(e1_lz$clock)
    );
    texture_coords$e2_valid e2_valid(
        .d(e2_valid$d),
        .q(e2_valid$q),
        .clock(e2_valid$clock)
    );
    texture_coords$e2_zero e2_zero(
        .d(e2_zero$d),
        .q(e2_zero$q),
        .clock(e2_zero$clock)
    );
    texture_coords$e2_st$0 e2_st$0(
        .d(e2_st$0$d),
        .q(e2_st$0$q),
        .clock(e2_st$0$clock)
    );
    texture_coords$e2_st$1 e2_st$1(
        .d(e2_st$1$d),
        .q(e2_st$1$q),
        .clock(e2_st$1$clock)
    );
    texture_coords$e2_p$0 e2_p$0(
        .d(e2_p$0$d),
        .q(e2_p$0$q),
        .clock(e2_p$0$clock)
    );
    texture_coords$e2_p$1 e2_p$1(
        .d(e2_p$1$d),
        .q(e2_p$1$q),
        .clock(e2_p$1$clock)
    );
    texture_coords$e2_idx$0 e2_idx$0(
        .d(e2_idx$0$d),
        .q(e2_idx$0$q),
        .clock(e2_idx$0$clock)
    );
    texture_coords$e2_idx$1 e2_idx$1(
        .d(e2_idx$1$d),
        .q(e2_idx$1$q),
        .clock(e2_idx$1$clock)
    );
    texture_coords$e2_lz e2_lz(
        .d(e2_lz$d),
        .q(e2_lz$q),
        .clock(e2_lz$clock)
    );
    texture_coords$log_m log_m(
        .address(log_m$address),
        .clock(log_m$clock),
        .data(log_m$data)
    );
    texture_coords$log_r log_r(
        .address(log_r$address),
        .clock(log_r$clock),
        .data(log_r$data)
    );
    texture_coords$e_valid e_valid(
        .d(e_valid$d),
        .q(e_valid$q),
        .clock(e_valid$clock)
    );
    texture_coords$e_st$0 e_st$0(
        .d(e_st$0$d),
        .q(e_st$0$q),
        .clock(e_st$0$clock)
    );
    texture_coords$e_st$1 e_st$1(
        .d(e_st$1$d),
        .q(e_st$1$q),
        .clock(e_st$1$clock)
    );
    texture_coords$e_lambda e_lambda(
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
    
endmodule // texture_coords


module texture_coords$b1_dq$0(d,q,clock);
    
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
          
endmodule // texture_coords$b1_dq$0


module texture_coords$b1_dq$1(d,q,clock);
    
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
          
endmodule // texture_coords$b1_dq$1


module texture_coords$b1_dxq$0(d,q,clock);
    
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
          
endmodule // texture_coords$b1_dxq$0


module texture_coords$b1_dxq$1(d,q,clock);
    
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
          
endmodule // texture_coords$b1_dxq$1


module texture_coords$b1_dxq$2(d,q,clock);
    
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
          
endmodule // texture_coords$b1_dxq$2


module texture_coords$b1_dxq$3(d,q,clock);
    
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
          
endmodule // texture_coords$b1_dxq$3


module texture_coords$b1_hs(d,q,clock);
    
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
          
endmodule // texture_coords$b1_hs


module texture_coords$b1_lz(d,q,clock);
    
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
          
endmodule // texture_coords$b1_lz


module texture_coords$b1_p$0(d,q,clock);
    
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
          
endmodule // texture_coords$b1_p$0


module texture_coords$b1_p$1(d,q,clock);
    
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
          
endmodule // texture_coords$b1_p$1


module texture_coords$b1_r(d,q,clock);
    
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
          
endmodule // texture_coords$b1_r


module texture_coords$b1_sh(d,q,clock);
    
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
          
endmodule // texture_coords$b1_sh


module texture_coords$b1_valid(d,q,clock);
    
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
          
endmodule // texture_coords$b1_valid


module texture_coords$b1_ws(d,q,clock);
    
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
          
endmodule // texture_coords$b1_ws


module texture_coords$b_dq$0(d,q,clock);
    
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
          
endmodule // texture_coords$b_dq$0


module texture_coords$b_dq$1(d,q,clock);
    
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
          
endmodule // texture_coords$b_dq$1


module texture_coords$b_dxq$0(d,q,clock);
    
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
          
endmodule // texture_coords$b_dxq$0


module texture_coords$b_dxq$1(d,q,clock);
    
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
          
endmodule // texture_coords$b_dxq$1


module texture_coords$b_dxq$2(d,q,clock);
    
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
          
endmodule // texture_coords$b_dxq$2


module texture_coords$b_dxq$3(d,q,clock);
    
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
          
endmodule // texture_coords$b_dxq$3


module texture_coords$b_hs(d,q,clock);
    
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
          
endmodule // texture_coords$b_hs


module texture_coords$b_lz(d,q,clock);
    
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
          
endmodule // texture_coords$b_lz


module texture_coords$b_r(d,q,clock);
    
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
          
endmodule // texture_coords$b_r


module texture_coords$b_st$0(d,q,clock);
    
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
          
endmodule // texture_coords$b_st$0


module texture_coords$b_st$1(d,q,clock);
    
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
          
endmodule // texture_coords$b_st$1


module texture_coords$b_valid(d,q,clock);
    
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
          
endmodule // texture_coords$b_valid


module texture_coords$b_ws(d,q,clock);
    
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
          
endmodule // texture_coords$b_ws


module texture_coords$c1_dxq$0(d,q,clock);
    
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
          
endmodule // texture_coords$c1_dxq$0


module texture_coords$c1_dxq$1(d,q,clock);
    
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
          
endmodule // texture_coords$c1_dxq$1


module texture_coords$c1_dxq$2(d,q,clock);
    
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
          
endmodule // texture_coords$c1_dxq$2


module texture_coords$c1_dxq$3(d,q,clock);
    
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
          
endmodule // texture_coords$c1_dxq$3


module texture_coords$c1_hs(d,q,clock);
    
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
          
endmodule // texture_coords$c1_hs


module texture_coords$c1_lz(d,q,clock);
    
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
          
endmodule // texture_coords$c1_lz


module texture_coords$c1_p$0(d,q,clock);
    
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
          
endmodule // texture_coords$c1_p$0


module texture_coords$c1_p$1(d,q,clock);
    
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
          
endmodule // texture_coords$c1_p$1


module texture_coords$c1_p$2(d,q,clock);
    
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
          
endmodule // texture_coords$c1_p$2


module texture_coords$c1_p$3(d,q,clock);
    
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
          
endmodule // texture_coords$c1_p$3


module texture_coords$c1_r(d,q,clock);
    
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
          
endmodule // texture_coords$c1_r


module texture_coords$c1_st$0(d,q,clock);
    
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
          
endmodule // texture_coords$c1_st$0


module texture_coords$c1_st$1(d,q,clock);
    
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
          
endmodule // texture_coords$c1_st$1


module texture_coords$c1_valid(d,q,clock);
    
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
          
endmodule // texture_coords$c1_valid


module texture_coords$c1_ws(d,q,clock);
    
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
          
endmodule // texture_coords$c1_ws


module texture_coords$c_lz(d,q,clock);
    
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
          
endmodule // texture_coords$c_lz


module texture_coords$c_r(d,q,clock);
    
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
          
endmodule // texture_coords$c_r


module texture_coords$c_st$0(d,q,clock);
    
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
          
endmodule // texture_coords$c_st$0


module texture_coords$c_st$1(d,q,clock);
    
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
          
endmodule // texture_coords$c_st$1


module texture_coords$c_u$0(d,q,clock);
    
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
          
endmodule // texture_coords$c_u$0


module texture_coords$c_u$1(d,q,clock);
    
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
          
endmodule // texture_coords$c_u$1


module texture_coords$c_u$2(d,q,clock);
    
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
          
endmodule // texture_coords$c_u$2


module texture_coords$c_u$3(d,q,clock);
    
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
          
endmodule // texture_coords$c_u$3


module texture_coords$c_valid(d,q,clock);
    
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
          
endmodule // texture_coords$c_valid


module texture_coords$d_lz(d,q,clock);
    
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
          
endmodule // texture_coords$d_lz


module texture_coords$d_m(d,q,clock);
    
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
          
endmodule // texture_coords$d_m


module texture_coords$d_r(d,q,clock);
    
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
          
endmodule // texture_coords$d_r


module texture_coords$d_st$0(d,q,clock);
    
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
          
endmodule // texture_coords$d_st$0


module texture_coords$d_st$1(d,q,clock);
    
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
          
endmodule // texture_coords$d_st$1


module texture_coords$d_valid(d,q,clock);
    
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
          
endmodule // texture_coords$d_valid


module texture_coords$dl_dq_x$0(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dq_x$0


module texture_coords$dl_dq_x$1(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dq_x$1


module texture_coords$dl_dq_x$10(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dq_x$10


module texture_coords$dl_dq_x$11(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dq_x$11


module texture_coords$dl_dq_x$12(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dq_x$12


module texture_coords$dl_dq_x$2(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dq_x$2


module texture_coords$dl_dq_x$3(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dq_x$3


module texture_coords$dl_dq_x$4(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dq_x$4


module texture_coords$dl_dq_x$5(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dq_x$5


module texture_coords$dl_dq_x$6(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dq_x$6


module texture_coords$dl_dq_x$7(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dq_x$7


module texture_coords$dl_dq_x$8(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dq_x$8


module texture_coords$dl_dq_x$9(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dq_x$9


module texture_coords$dl_dq_y$0(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dq_y$0


module texture_coords$dl_dq_y$1(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dq_y$1


module texture_coords$dl_dq_y$10(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dq_y$10


module texture_coords$dl_dq_y$11(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dq_y$11


module texture_coords$dl_dq_y$12(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dq_y$12


module texture_coords$dl_dq_y$2(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dq_y$2


module texture_coords$dl_dq_y$3(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dq_y$3


module texture_coords$dl_dq_y$4(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dq_y$4


module texture_coords$dl_dq_y$5(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dq_y$5


module texture_coords$dl_dq_y$6(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dq_y$6


module texture_coords$dl_dq_y$7(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dq_y$7


module texture_coords$dl_dq_y$8(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dq_y$8


module texture_coords$dl_dq_y$9(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dq_y$9


module texture_coords$dl_dsq_x$0(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dsq_x$0


module texture_coords$dl_dsq_x$1(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dsq_x$1


module texture_coords$dl_dsq_x$10(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dsq_x$10


module texture_coords$dl_dsq_x$11(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dsq_x$11


module texture_coords$dl_dsq_x$12(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dsq_x$12


module texture_coords$dl_dsq_x$2(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dsq_x$2


module texture_coords$dl_dsq_x$3(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dsq_x$3


module texture_coords$dl_dsq_x$4(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dsq_x$4


module texture_coords$dl_dsq_x$5(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dsq_x$5


module texture_coords$dl_dsq_x$6(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dsq_x$6


module texture_coords$dl_dsq_x$7(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dsq_x$7


module texture_coords$dl_dsq_x$8(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dsq_x$8


module texture_coords$dl_dsq_x$9(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dsq_x$9


module texture_coords$dl_dsq_y$0(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dsq_y$0


module texture_coords$dl_dsq_y$1(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dsq_y$1


module texture_coords$dl_dsq_y$10(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dsq_y$10


module texture_coords$dl_dsq_y$11(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dsq_y$11


module texture_coords$dl_dsq_y$12(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dsq_y$12


module texture_coords$dl_dsq_y$2(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dsq_y$2


module texture_coords$dl_dsq_y$3(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dsq_y$3


module texture_coords$dl_dsq_y$4(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dsq_y$4


module texture_coords$dl_dsq_y$5(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dsq_y$5


module texture_coords$dl_dsq_y$6(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dsq_y$6


module texture_coords$dl_dsq_y$7(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dsq_y$7


module texture_coords$dl_dsq_y$8(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dsq_y$8


module texture_coords$dl_dsq_y$9(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dsq_y$9


module texture_coords$dl_dtq_x$0(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dtq_x$0


module texture_coords$dl_dtq_x$1(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dtq_x$1


module texture_coords$dl_dtq_x$10(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dtq_x$10


module texture_coords$dl_dtq_x$11(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dtq_x$11


module texture_coords$dl_dtq_x$12(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dtq_x$12


module texture_coords$dl_dtq_x$2(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dtq_x$2


module texture_coords$dl_dtq_x$3(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dtq_x$3


module texture_coords$dl_dtq_x$4(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dtq_x$4


module texture_coords$dl_dtq_x$5(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dtq_x$5


module texture_coords$dl_dtq_x$6(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dtq_x$6


module texture_coords$dl_dtq_x$7(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dtq_x$7


module texture_coords$dl_dtq_x$8(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dtq_x$8


module texture_coords$dl_dtq_x$9(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dtq_x$9


module texture_coords$dl_dtq_y$0(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dtq_y$0


module texture_coords$dl_dtq_y$1(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dtq_y$1


module texture_coords$dl_dtq_y$10(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dtq_y$10


module texture_coords$dl_dtq_y$11(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dtq_y$11


module texture_coords$dl_dtq_y$12(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dtq_y$12


module texture_coords$dl_dtq_y$2(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dtq_y$2


module texture_coords$dl_dtq_y$3(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dtq_y$3


module texture_coords$dl_dtq_y$4(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dtq_y$4


module texture_coords$dl_dtq_y$5(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dtq_y$5


module texture_coords$dl_dtq_y$6(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dtq_y$6


module texture_coords$dl_dtq_y$7(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dtq_y$7


module texture_coords$dl_dtq_y$8(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dtq_y$8


module texture_coords$dl_dtq_y$9(d,q,clock);
    
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
          
endmodule // texture_coords$dl_dtq_y$9


module texture_coords$dl_hs$0(d,q,clock);
    
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
          
endmodule // texture_coords$dl_hs$0


module texture_coords$dl_hs$1(d,q,clock);
    
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
          
endmodule // texture_coords$dl_hs$1


module texture_coords$dl_hs$10(d,q,clock);
    
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
          
endmodule // texture_coords$dl_hs$10


module texture_coords$dl_hs$11(d,q,clock);
    
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
          
endmodule // texture_coords$dl_hs$11


module texture_coords$dl_hs$12(d,q,clock);
    
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
          
endmodule // texture_coords$dl_hs$12


module texture_coords$dl_hs$2(d,q,clock);
    
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
          
endmodule // texture_coords$dl_hs$2


module texture_coords$dl_hs$3(d,q,clock);
    
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
          
endmodule // texture_coords$dl_hs$3


module texture_coords$dl_hs$4(d,q,clock);
    
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
          
endmodule // texture_coords$dl_hs$4


module texture_coords$dl_hs$5(d,q,clock);
    
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
          
endmodule // texture_coords$dl_hs$5


module texture_coords$dl_hs$6(d,q,clock);
    
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
          
endmodule // texture_coords$dl_hs$6


module texture_coords$dl_hs$7(d,q,clock);
    
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
          
endmodule // texture_coords$dl_hs$7


module texture_coords$dl_hs$8(d,q,clock);
    
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
          
endmodule // texture_coords$dl_hs$8


module texture_coords$dl_hs$9(d,q,clock);
    
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
          
endmodule // texture_coords$dl_hs$9


module texture_coords$dl_lz$0(d,q,clock);
    
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
          
endmodule // texture_coords$dl_lz$0


module texture_coords$dl_lz$1(d,q,clock);
    
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
          
endmodule // texture_coords$dl_lz$1


module texture_coords$dl_lz$10(d,q,clock);
    
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
          
endmodule // texture_coords$dl_lz$10


module texture_coords$dl_lz$11(d,q,clock);
    
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
          
endmodule // texture_coords$dl_lz$11


module texture_coords$dl_lz$12(d,q,clock);
    
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
          
endmodule // texture_coords$dl_lz$12


module texture_coords$dl_lz$2(d,q,clock);
    
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
          
endmodule // texture_coords$dl_lz$2


module texture_coords$dl_lz$3(d,q,clock);
    
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
          
endmodule // texture_coords$dl_lz$3


module texture_coords$dl_lz$4(d,q,clock);
    
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
          
endmodule // texture_coords$dl_lz$4


module texture_coords$dl_lz$5(d,q,clock);
    
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
          
endmodule // texture_coords$dl_lz$5


module texture_coords$dl_lz$6(d,q,clock);
    
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
          
endmodule // texture_coords$dl_lz$6


module texture_coords$dl_lz$7(d,q,clock);
    
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
          
endmodule // texture_coords$dl_lz$7


module texture_coords$dl_lz$8(d,q,clock);
    
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
          
endmodule // texture_coords$dl_lz$8


module texture_coords$dl_lz$9(d,q,clock);
    
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
          
endmodule // texture_coords$dl_lz$9


module texture_coords$dl_sq$0(d,q,clock);
    
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
          
endmodule // texture_coords$dl_sq$0


module texture_coords$dl_sq$1(d,q,clock);
    
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
          
endmodule // texture_coords$dl_sq$1


module texture_coords$dl_sq$10(d,q,clock);
    
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
          
endmodule // texture_coords$dl_sq$10


module texture_coords$dl_sq$11(d,q,clock);
    
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
          
endmodule // texture_coords$dl_sq$11


module texture_coords$dl_sq$12(d,q,clock);
    
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
          
endmodule // texture_coords$dl_sq$12


module texture_coords$dl_sq$2(d,q,clock);
    
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
          
endmodule // texture_coords$dl_sq$2


module texture_coords$dl_sq$3(d,q,clock);
    
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
          
endmodule // texture_coords$dl_sq$3


module texture_coords$dl_sq$4(d,q,clock);
    
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
          
endmodule // texture_coords$dl_sq$4


module texture_coords$dl_sq$5(d,q,clock);
    
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
          
endmodule // texture_coords$dl_sq$5


module texture_coords$dl_sq$6(d,q,clock);
    
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
          
endmodule // texture_coords$dl_sq$6


module texture_coords$dl_sq$7(d,q,clock);
    
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
          
endmodule // texture_coords$dl_sq$7


module texture_coords$dl_sq$8(d,q,clock);
    
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
          
endmodule // texture_coords$dl_sq$8


module texture_coords$dl_sq$9(d,q,clock);
    
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
          
endmodule // texture_coords$dl_sq$9


module texture_coords$dl_tq$0(d,q,clock);
    
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
          
endmodule // texture_coords$dl_tq$0


module texture_coords$dl_tq$1(d,q,clock);
    
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
          
endmodule // texture_coords$dl_tq$1


module texture_coords$dl_tq$10(d,q,clock);
    
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
          
endmodule // texture_coords$dl_tq$10


module texture_coords$dl_tq$11(d,q,clock);
    
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
          
endmodule // texture_coords$dl_tq$11


module texture_coords$dl_tq$12(d,q,clock);
    
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
          
endmodule // texture_coords$dl_tq$12


module texture_coords$dl_tq$2(d,q,clock);
    
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
          
endmodule // texture_coords$dl_tq$2


module texture_coords$dl_tq$3(d,q,clock);
    
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
          
endmodule // texture_coords$dl_tq$3


module texture_coords$dl_tq$4(d,q,clock);
    
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
          
endmodule // texture_coords$dl_tq$4


module texture_coords$dl_tq$5(d,q,clock);
    
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
          
endmodule // texture_coords$dl_tq$5


module texture_coords$dl_tq$6(d,q,clock);
    
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
          
endmodule // texture_coords$dl_tq$6


module texture_coords$dl_tq$7(d,q,clock);
    
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
          
endmodule // texture_coords$dl_tq$7


module texture_coords$dl_tq$8(d,q,clock);
    
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
          
endmodule // texture_coords$dl_tq$8


module texture_coords$dl_tq$9(d,q,clock);
    
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
          
endmodule // texture_coords$dl_tq$9


module texture_coords$dl_ws$0(d,q,clock);
    
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
          
endmodule // texture_coords$dl_ws$0


module texture_coords$dl_ws$1(d,q,clock);
    
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
          
endmodule // texture_coords$dl_ws$1


module texture_coords$dl_ws$10(d,q,clock);
    
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
          
endmodule // texture_coords$dl_ws$10


module texture_coords$dl_ws$11(d,q,clock);
    
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
          
endmodule // texture_coords$dl_ws$11


module texture_coords$dl_ws$12(d,q,clock);
    
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
          
endmodule // texture_coords$dl_ws$12


module texture_coords$dl_ws$2(d,q,clock);
    
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
          
endmodule // texture_coords$dl_ws$2


module texture_coords$dl_ws$3(d,q,clock);
    
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
          
endmodule // texture_coords$dl_ws$3


module texture_coords$dl_ws$4(d,q,clock);
    
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
          
endmodule // texture_coords$dl_ws$4


module texture_coords$dl_ws$5(d,q,clock);
    
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
          
endmodule // texture_coords$dl_ws$5


module texture_coords$dl_ws$6(d,q,clock);
    
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
          
endmodule // texture_coords$dl_ws$6


module texture_coords$dl_ws$7(d,q,clock);
    
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
          
endmodule // texture_coords$dl_ws$7


module texture_coords$dl_ws$8(d,q,clock);
    
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
          
endmodule // texture_coords$dl_ws$8


module texture_coords$dl_ws$9(d,q,clock);
    
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
          
endmodule // texture_coords$dl_ws$9


module texture_coords$e1_idx$0(d,q,clock);
    
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
          
endmodule // texture_coords$e1_idx$0


module texture_coords$e1_idx$1(d,q,clock);
    
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
          
endmodule // texture_coords$e1_idx$1


module texture_coords$e1_lz(d,q,clock);
    
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
          
endmodule // texture_coords$e1_lz


module texture_coords$e1_p$0(d,q,clock);
    
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
          
endmodule // texture_coords$e1_p$0


module texture_coords$e1_p$1(d,q,clock);
    
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
          
endmodule // texture_coords$e1_p$1


module texture_coords$e1_st$0(d,q,clock);
    
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
          
endmodule // texture_coords$e1_st$0


module texture_coords$e1_st$1(d,q,clock);
    
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
          
endmodule // texture_coords$e1_st$1


module texture_coords$e1_valid(d,q,clock);
    
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
          
endmodule // texture_coords$e1_valid


module texture_coords$e1_zero(d,q,clock);
    
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
          
endmodule // texture_coords$e1_zero


module texture_coords$e2_idx$0(d,q,clock);
    
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
          
endmodule // texture_coords$e2_idx$0


module texture_coords$e2_idx$1(d,q,clock);
    
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
          
endmodule // texture_coords$e2_idx$1


module texture_coords$e2_lz(d,q,clock);
    
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
          
endmodule // texture_coords$e2_lz


module texture_coords$e2_p$0(d,q,clock);
    
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
          
endmodule // texture_coords$e2_p$0


module texture_coords$e2_p$1(d,q,clock);
    
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
          
endmodule // texture_coords$e2_p$1


module texture_coords$e2_st$0(d,q,clock);
    
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
          
endmodule // texture_coords$e2_st$0


module texture_coords$e2_st$1(d,q,clock);
    
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
          
endmodule // texture_coords$e2_st$1


module texture_coords$e2_valid(d,q,clock);
    
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
          
endmodule // texture_coords$e2_valid


module texture_coords$e2_zero(d,q,clock);
    
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
          
endmodule // texture_coords$e2_zero


module texture_coords$e_lambda(d,q,clock);
    
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
          
endmodule // texture_coords$e_lambda


module texture_coords$e_st$0(d,q,clock);
    
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
          
endmodule // texture_coords$e_st$0


module texture_coords$e_st$1(d,q,clock);
    
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
          
endmodule // texture_coords$e_st$1


module texture_coords$e_valid(d,q,clock);
    
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
          
endmodule // texture_coords$e_valid


module texture_coords$log_m(address,clock,data);
    
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
endmodule // texture_coords$log_m


module texture_coords$log_r(address,clock,data);
    
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
endmodule // texture_coords$log_r


module texture_coords$mul_g$0(a,b,p);
    
    // Module arguments
    input wire  [28:0] a;
    input wire  [29:0] b;
    output reg  [58:0] p;
    
    // Update code (custom)
    // p = low 59 bits of a * b, both signed: a signed 59-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_coords$mul_g$0


module texture_coords$mul_g$1(a,b,p);
    
    // Module arguments
    input wire  [28:0] a;
    input wire  [29:0] b;
    output reg  [58:0] p;
    
    // Update code (custom)
    // p = low 59 bits of a * b, both signed: a signed 59-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_coords$mul_g$1


module texture_coords$mul_g$2(a,b,p);
    
    // Module arguments
    input wire  [28:0] a;
    input wire  [29:0] b;
    output reg  [58:0] p;
    
    // Update code (custom)
    // p = low 59 bits of a * b, both signed: a signed 59-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_coords$mul_g$2


module texture_coords$mul_g$3(a,b,p);
    
    // Module arguments
    input wire  [28:0] a;
    input wire  [29:0] b;
    output reg  [58:0] p;
    
    // Update code (custom)
    // p = low 59 bits of a * b, both signed: a signed 59-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_coords$mul_g$3


module texture_coords$mul_s(a,b,p);
    
    // Module arguments
    input wire  [28:0] a;
    input wire  [26:0] b;
    output reg  [55:0] p;
    
    // Update code (custom)
    // p = low 56 bits of a * b, both signed: a signed 56-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_coords$mul_s


module texture_coords$mul_sq$0(a,b,p);
    
    // Module arguments
    input wire  [47:0] a;
    input wire  [47:0] b;
    output reg  [95:0] p;
    
    // Update code (custom)
    // p = low 96 bits of a * b, both signed: a signed 96-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_coords$mul_sq$0


module texture_coords$mul_sq$1(a,b,p);
    
    // Module arguments
    input wire  [47:0] a;
    input wire  [47:0] b;
    output reg  [95:0] p;
    
    // Update code (custom)
    // p = low 96 bits of a * b, both signed: a signed 96-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_coords$mul_sq$1


module texture_coords$mul_sq$2(a,b,p);
    
    // Module arguments
    input wire  [47:0] a;
    input wire  [47:0] b;
    output reg  [95:0] p;
    
    // Update code (custom)
    // p = low 96 bits of a * b, both signed: a signed 96-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_coords$mul_sq$2


module texture_coords$mul_sq$3(a,b,p);
    
    // Module arguments
    input wire  [47:0] a;
    input wire  [47:0] b;
    output reg  [95:0] p;
    
    // Update code (custom)
    // p = low 96 bits of a * b, both signed: a signed 96-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_coords$mul_sq$3


module texture_coords$mul_t(a,b,p);
    
    // Module arguments
    input wire  [28:0] a;
    input wire  [26:0] b;
    output reg  [55:0] p;
    
    // Update code (custom)
    // p = low 56 bits of a * b, both signed: a signed 56-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_coords$mul_t


module texture_coords$num$0(dxq,p,size_log2,u);
    
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
    
endmodule // texture_coords$num$0


module texture_coords$num$1(dxq,p,size_log2,u);
    
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
    
endmodule // texture_coords$num$1


module texture_coords$num$2(dxq,p,size_log2,u);
    
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
    
endmodule // texture_coords$num$2


module texture_coords$num$3(dxq,p,size_log2,u);
    
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
    
endmodule // texture_coords$num$3


module texture_coords$recip(clock,inp_valid,inp_ready,hold,inp_n,inp_d,out_valid,out_ready,out_q,out_r);
    
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
    texture_coords$recip$stages$0 stages$0(
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
    texture_coords$recip$stages$1 stages$1(
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
    texture_coords$recip$stages$2 stages$2(
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
    texture_coords$recip$stages$3 stages$3(
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
    texture_coords$recip$stages$4 stages$4(
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
    texture_coords$recip$stages$5 stages$5(
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
    texture_coords$recip$stages$6 stages$6(
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
    texture_coords$recip$stages$7 stages$7(
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
    texture_coords$recip$stages$8 stages$8(
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
    texture_coords$recip$stages$9 stages$9(
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
    texture_coords$recip$stages$10 stages$10(
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
    texture_coords$recip$stages$11 stages$11(
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
    texture_coords$recip$stages$12 stages$12(
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
    
endmodule // texture_coords$recip


module texture_coords$recip$stages$0(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
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
    texture_coords$recip$stages$0$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    texture_coords$recip$stages$0$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    texture_coords$recip$stages$0$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    texture_coords$recip$stages$0$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    texture_coords$recip$stages$0$neg_r neg_r(
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
    
endmodule // texture_coords$recip$stages$0


module texture_coords$recip$stages$0$d_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$0$d_r


module texture_coords$recip$stages$0$neg_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$0$neg_r


module texture_coords$recip$stages$0$p_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$0$p_r


module texture_coords$recip$stages$0$valid_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$0$valid_r


module texture_coords$recip$stages$0$x_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$0$x_r


module texture_coords$recip$stages$1(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
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
    texture_coords$recip$stages$1$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    texture_coords$recip$stages$1$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    texture_coords$recip$stages$1$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    texture_coords$recip$stages$1$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    texture_coords$recip$stages$1$neg_r neg_r(
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
    
endmodule // texture_coords$recip$stages$1


module texture_coords$recip$stages$1$d_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$1$d_r


module texture_coords$recip$stages$1$neg_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$1$neg_r


module texture_coords$recip$stages$1$p_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$1$p_r


module texture_coords$recip$stages$1$valid_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$1$valid_r


module texture_coords$recip$stages$1$x_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$1$x_r


module texture_coords$recip$stages$10(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
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
    texture_coords$recip$stages$10$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    texture_coords$recip$stages$10$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    texture_coords$recip$stages$10$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    texture_coords$recip$stages$10$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    texture_coords$recip$stages$10$neg_r neg_r(
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
    
endmodule // texture_coords$recip$stages$10


module texture_coords$recip$stages$10$d_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$10$d_r


module texture_coords$recip$stages$10$neg_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$10$neg_r


module texture_coords$recip$stages$10$p_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$10$p_r


module texture_coords$recip$stages$10$valid_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$10$valid_r


module texture_coords$recip$stages$10$x_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$10$x_r


module texture_coords$recip$stages$11(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
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
    texture_coords$recip$stages$11$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    texture_coords$recip$stages$11$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    texture_coords$recip$stages$11$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    texture_coords$recip$stages$11$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    texture_coords$recip$stages$11$neg_r neg_r(
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
    
endmodule // texture_coords$recip$stages$11


module texture_coords$recip$stages$11$d_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$11$d_r


module texture_coords$recip$stages$11$neg_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$11$neg_r


module texture_coords$recip$stages$11$p_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$11$p_r


module texture_coords$recip$stages$11$valid_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$11$valid_r


module texture_coords$recip$stages$11$x_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$11$x_r


module texture_coords$recip$stages$12(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
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
    texture_coords$recip$stages$12$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    texture_coords$recip$stages$12$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    texture_coords$recip$stages$12$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    texture_coords$recip$stages$12$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    texture_coords$recip$stages$12$neg_r neg_r(
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
    
endmodule // texture_coords$recip$stages$12


module texture_coords$recip$stages$12$d_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$12$d_r


module texture_coords$recip$stages$12$neg_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$12$neg_r


module texture_coords$recip$stages$12$p_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$12$p_r


module texture_coords$recip$stages$12$valid_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$12$valid_r


module texture_coords$recip$stages$12$x_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$12$x_r


module texture_coords$recip$stages$2(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
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
    texture_coords$recip$stages$2$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    texture_coords$recip$stages$2$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    texture_coords$recip$stages$2$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    texture_coords$recip$stages$2$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    texture_coords$recip$stages$2$neg_r neg_r(
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
    
endmodule // texture_coords$recip$stages$2


module texture_coords$recip$stages$2$d_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$2$d_r


module texture_coords$recip$stages$2$neg_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$2$neg_r


module texture_coords$recip$stages$2$p_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$2$p_r


module texture_coords$recip$stages$2$valid_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$2$valid_r


module texture_coords$recip$stages$2$x_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$2$x_r


module texture_coords$recip$stages$3(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
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
    texture_coords$recip$stages$3$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    texture_coords$recip$stages$3$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    texture_coords$recip$stages$3$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    texture_coords$recip$stages$3$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    texture_coords$recip$stages$3$neg_r neg_r(
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
    
endmodule // texture_coords$recip$stages$3


module texture_coords$recip$stages$3$d_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$3$d_r


module texture_coords$recip$stages$3$neg_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$3$neg_r


module texture_coords$recip$stages$3$p_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$3$p_r


module texture_coords$recip$stages$3$valid_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$3$valid_r


module texture_coords$recip$stages$3$x_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$3$x_r


module texture_coords$recip$stages$4(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
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
    texture_coords$recip$stages$4$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    texture_coords$recip$stages$4$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    texture_coords$recip$stages$4$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    texture_coords$recip$stages$4$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    texture_coords$recip$stages$4$neg_r neg_r(
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
    
endmodule // texture_coords$recip$stages$4


module texture_coords$recip$stages$4$d_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$4$d_r


module texture_coords$recip$stages$4$neg_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$4$neg_r


module texture_coords$recip$stages$4$p_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$4$p_r


module texture_coords$recip$stages$4$valid_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$4$valid_r


module texture_coords$recip$stages$4$x_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$4$x_r


module texture_coords$recip$stages$5(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
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
    texture_coords$recip$stages$5$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    texture_coords$recip$stages$5$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    texture_coords$recip$stages$5$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    texture_coords$recip$stages$5$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    texture_coords$recip$stages$5$neg_r neg_r(
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
    
endmodule // texture_coords$recip$stages$5


module texture_coords$recip$stages$5$d_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$5$d_r


module texture_coords$recip$stages$5$neg_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$5$neg_r


module texture_coords$recip$stages$5$p_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$5$p_r


module texture_coords$recip$stages$5$valid_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$5$valid_r


module texture_coords$recip$stages$5$x_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$5$x_r


module texture_coords$recip$stages$6(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
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
    texture_coords$recip$stages$6$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    texture_coords$recip$stages$6$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    texture_coords$recip$stages$6$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    texture_coords$recip$stages$6$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    texture_coords$recip$stages$6$neg_r neg_r(
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
    
endmodule // texture_coords$recip$stages$6


module texture_coords$recip$stages$6$d_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$6$d_r


module texture_coords$recip$stages$6$neg_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$6$neg_r


module texture_coords$recip$stages$6$p_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$6$p_r


module texture_coords$recip$stages$6$valid_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$6$valid_r


module texture_coords$recip$stages$6$x_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$6$x_r


module texture_coords$recip$stages$7(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
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
    texture_coords$recip$stages$7$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    texture_coords$recip$stages$7$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    texture_coords$recip$stages$7$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    texture_coords$recip$stages$7$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    texture_coords$recip$stages$7$neg_r neg_r(
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
    
endmodule // texture_coords$recip$stages$7


module texture_coords$recip$stages$7$d_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$7$d_r


module texture_coords$recip$stages$7$neg_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$7$neg_r


module texture_coords$recip$stages$7$p_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$7$p_r


module texture_coords$recip$stages$7$valid_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$7$valid_r


module texture_coords$recip$stages$7$x_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$7$x_r


module texture_coords$recip$stages$8(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
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
    texture_coords$recip$stages$8$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    texture_coords$recip$stages$8$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    texture_coords$recip$stages$8$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    texture_coords$recip$stages$8$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    texture_coords$recip$stages$8$neg_r neg_r(
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
    
endmodule // texture_coords$recip$stages$8


module texture_coords$recip$stages$8$d_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$8$d_r


module texture_coords$recip$stages$8$neg_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$8$neg_r


module texture_coords$recip$stages$8$p_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$8$p_r


module texture_coords$recip$stages$8$valid_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$8$valid_r


module texture_coords$recip$stages$8$x_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$8$x_r


module texture_coords$recip$stages$9(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
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
    texture_coords$recip$stages$9$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    texture_coords$recip$stages$9$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    texture_coords$recip$stages$9$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    texture_coords$recip$stages$9$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    texture_coords$recip$stages$9$neg_r neg_r(
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
    
endmodule // texture_coords$recip$stages$9


module texture_coords$recip$stages$9$d_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$9$d_r


module texture_coords$recip$stages$9$neg_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$9$neg_r


module texture_coords$recip$stages$9$p_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$9$p_r


module texture_coords$recip$stages$9$valid_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$9$valid_r


module texture_coords$recip$stages$9$x_r(d,q,clock);
    
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
          
endmodule // texture_coords$recip$stages$9$x_r
