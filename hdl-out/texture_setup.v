

module texture_setup(clock,start,tri$x0,tri$y0,tri$x1,tri$y1,tri$x2,tri$y2,tri$sq0,tri$sq1,tri$sq2,tri$tq0,tri$tq1,tri$tq2,tri$q0,tri$q1,tri$q2,tri$mant,tri$exp,done,dsq_x,dsq_y,dtq_x,dtq_y,dq_x,dq_y,en,inp_valid,inp_x,inp_y,out_valid,out_sq,out_tq,out_q);
    
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
    texture_setup$step step(
        .d(step$d),
        .q(step$q),
        .clock(step$clock)
    );
    texture_setup$busy busy(
        .d(busy$d),
        .q(busy$q),
        .clock(busy$clock)
    );
    texture_setup$done_r done_r(
        .d(done_r$d),
        .q(done_r$q),
        .clock(done_r$clock)
    );
    texture_setup$neg neg(
        .d(neg$d),
        .q(neg$q),
        .clock(neg$clock)
    );
    texture_setup$sx_pos$0 sx_pos$0(
        .x(sx_pos$0$x),
        .y(sx_pos$0$y)
    );
    texture_setup$sx_pos$1 sx_pos$1(
        .x(sx_pos$1$x),
        .y(sx_pos$1$y)
    );
    texture_setup$sx_pos$2 sx_pos$2(
        .x(sx_pos$2$x),
        .y(sx_pos$2$y)
    );
    texture_setup$sx_pos$3 sx_pos$3(
        .x(sx_pos$3$x),
        .y(sx_pos$3$y)
    );
    texture_setup$sx_pos$4 sx_pos$4(
        .x(sx_pos$4$x),
        .y(sx_pos$4$y)
    );
    texture_setup$sx_pos$5 sx_pos$5(
        .x(sx_pos$5$x),
        .y(sx_pos$5$y)
    );
    texture_setup$sx_st$0 sx_st$0(
        .x(sx_st$0$x),
        .y(sx_st$0$y)
    );
    texture_setup$sx_st$1 sx_st$1(
        .x(sx_st$1$x),
        .y(sx_st$1$y)
    );
    texture_setup$sx_st$2 sx_st$2(
        .x(sx_st$2$x),
        .y(sx_st$2$y)
    );
    texture_setup$sx_st$3 sx_st$3(
        .x(sx_st$3$x),
        .y(sx_st$3$y)
    );
    texture_setup$sx_st$4 sx_st$4(
        .x(sx_st$4$x),
        .y(sx_st$4$y)
    );
    texture_setup$sx_st$5 sx_st$5(
        .x(sx_st$5$x),
        .y(sx_st$5$y)
    );
    texture_setup$e1x e1x(
        .d(e1x$d),
        .q(e1x$q),
        .clock(e1x$clock)
    );
    texture_setup$e1y e1y(
        .d(e1y$d),
        .q(e1y$q),
        .clock(e1y$clock)
    );
    texture_setup$e2x e2x(
        .d(e2x$d),
        .q(e2x$q),
        .clock(e2x$clock)
    );
    texture_setup$e2y e2y(
        .d(e2y$d),
        .q(e2y$q),
        .clock(e2y$clock)
    );
    texture_setup$sx_e1x sx_e1x(
        .x(sx_e1x$x),
        .y(sx_e1x$y)
    );
    texture_setup$sx_e2x sx_e2x(
        .x(sx_e2x$x),
        .y(sx_e2x$y)
    );
    texture_setup$d1$0 d1$0(
        .d(d1$0$d),
        .q(d1$0$q),
        .clock(d1$0$clock)
    );
    texture_setup$d1$1 d1$1(
        .d(d1$1$d),
        .q(d1$1$q),
        .clock(d1$1$clock)
    );
    texture_setup$d1$2 d1$2(
        .d(d1$2$d),
        .q(d1$2$q),
        .clock(d1$2$clock)
    );
    texture_setup$d2$0 d2$0(
        .d(d2$0$d),
        .q(d2$0$q),
        .clock(d2$0$clock)
    );
    texture_setup$d2$1 d2$1(
        .d(d2$1$d),
        .q(d2$1$q),
        .clock(d2$1$clock)
    );
    texture_setup$d2$2 d2$2(
        .d(d2$2$d),
        .q(d2$2$q),
        .clock(d2$2$clock)
    );
    texture_setup$sx_d sx_d(
        .x(sx_d$x),
        .y(sx_d$y)
    );
    texture_setup$mant mant(
        .d(mant$d),
        .q(mant$q),
        .clock(mant$clock)
    );
    texture_setup$exp exp(
        .d(exp$d),
        .q(exp$q),
        .clock(exp$clock)
    );
    texture_setup$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    texture_setup$prod prod(
        .d(prod$d),
        .q(prod$q),
        .clock(prod$clock)
    );
    texture_setup$acc acc(
        .d(acc$d),
        .q(acc$q),
        .clock(acc$clock)
    );
    texture_setup$ox ox(
        .d(ox$d),
        .q(ox$q),
        .clock(ox$clock)
    );
    texture_setup$oy oy(
        .d(oy$d),
        .q(oy$q),
        .clock(oy$clock)
    );
    texture_setup$a0_sq a0_sq(
        .d(a0_sq$d),
        .q(a0_sq$q),
        .clock(a0_sq$clock)
    );
    texture_setup$a0_tq a0_tq(
        .d(a0_tq$d),
        .q(a0_tq$q),
        .clock(a0_tq$clock)
    );
    texture_setup$a0_q a0_q(
        .d(a0_q$d),
        .q(a0_q$q),
        .clock(a0_q$clock)
    );
    texture_setup$g_sq$0 g_sq$0(
        .d(g_sq$0$d),
        .q(g_sq$0$q),
        .clock(g_sq$0$clock)
    );
    texture_setup$g_sq$1 g_sq$1(
        .d(g_sq$1$d),
        .q(g_sq$1$q),
        .clock(g_sq$1$clock)
    );
    texture_setup$g_tq$0 g_tq$0(
        .d(g_tq$0$d),
        .q(g_tq$0$q),
        .clock(g_tq$0$clock)
    );
    texture_setup$g_tq$1 g_tq$1(
        .d(g_tq$1$d),
        .q(g_tq$1$q),
        .clock(g_tq$1$clock)
    );
    texture_setup$g_q$0 g_q$0(
        .d(g_q$0$d),
        .q(g_q$0$q),
        .clock(g_q$0$clock)
    );
    texture_setup$g_q$1 g_q$1(
        .d(g_q$1$d),
        .q(g_q$1$q),
        .clock(g_q$1$clock)
    );
    texture_setup$lod_sq$0 lod_sq$0(
        .d(lod_sq$0$d),
        .q(lod_sq$0$q),
        .clock(lod_sq$0$clock)
    );
    texture_setup$lod_sq$1 lod_sq$1(
        .d(lod_sq$1$d),
        .q(lod_sq$1$q),
        .clock(lod_sq$1$clock)
    );
    texture_setup$lod_tq$0 lod_tq$0(
        .d(lod_tq$0$d),
        .q(lod_tq$0$q),
        .clock(lod_tq$0$clock)
    );
    texture_setup$lod_tq$1 lod_tq$1(
        .d(lod_tq$1$d),
        .q(lod_tq$1$q),
        .clock(lod_tq$1$clock)
    );
    texture_setup$lod_q$0 lod_q$0(
        .d(lod_q$0$d),
        .q(lod_q$0$q),
        .clock(lod_q$0$clock)
    );
    texture_setup$lod_q$1 lod_q$1(
        .d(lod_q$1$d),
        .q(lod_q$1$q),
        .clock(lod_q$1$clock)
    );
    texture_setup$s1_valid s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    texture_setup$s1_x s1_x(
        .d(s1_x$d),
        .q(s1_x$q),
        .clock(s1_x$clock)
    );
    texture_setup$s1_y s1_y(
        .d(s1_y$d),
        .q(s1_y$q),
        .clock(s1_y$clock)
    );
    texture_setup$mul_sq$0 mul_sq$0(
        .a(mul_sq$0$a),
        .b(mul_sq$0$b),
        .p(mul_sq$0$p)
    );
    texture_setup$mul_sq$1 mul_sq$1(
        .a(mul_sq$1$a),
        .b(mul_sq$1$b),
        .p(mul_sq$1$p)
    );
    texture_setup$mul_tq$0 mul_tq$0(
        .a(mul_tq$0$a),
        .b(mul_tq$0$b),
        .p(mul_tq$0$p)
    );
    texture_setup$mul_tq$1 mul_tq$1(
        .a(mul_tq$1$a),
        .b(mul_tq$1$b),
        .p(mul_tq$1$p)
    );
    texture_setup$mul_q$0 mul_q$0(
        .a(mul_q$0$a),
        .b(mul_q$0$b),
        .p(mul_q$0$p)
    );
    texture_setup$mul_q$1 mul_q$1(
        .a(mul_q$1$a),
        .b(mul_q$1$b),
        .p(mul_q$1$p)
    );
    texture_setup$s2_valid s2_valid(
        .d(s2_valid$d),
        .q(s2_valid$q),
        .clock(s2_valid$clock)
    );
    texture_setup$s2_sq$0 s2_sq$0(
        .d(s2_sq$0$d),
        .q(s2_sq$0$q),
        .clock(s2_sq$0$clock)
    );
    texture_setup$s2_sq$1 s2_sq$1(
        .d(s2_sq$1$d),
        .q(s2_sq$1$q),
        .clock(s2_sq$1$clock)
    );
    texture_setup$s2_tq$0 s2_tq$0(
        .d(s2_tq$0$d),
        .q(s2_tq$0$q),
        .clock(s2_tq$0$clock)
    );
    texture_setup$s2_tq$1 s2_tq$1(
        .d(s2_tq$1$d),
        .q(s2_tq$1$q),
        .clock(s2_tq$1$clock)
    );
    texture_setup$s2_q$0 s2_q$0(
        .d(s2_q$0$d),
        .q(s2_q$0$q),
        .clock(s2_q$0$clock)
    );
    texture_setup$s2_q$1 s2_q$1(
        .d(s2_q$1$d),
        .q(s2_q$1$q),
        .clock(s2_q$1$clock)
    );
    texture_setup$s3_valid s3_valid(
        .d(s3_valid$d),
        .q(s3_valid$q),
        .clock(s3_valid$clock)
    );
    texture_setup$s3_sq s3_sq(
        .d(s3_sq$d),
        .q(s3_sq$q),
        .clock(s3_sq$clock)
    );
    texture_setup$s3_tq s3_tq(
        .d(s3_tq$d),
        .q(s3_tq$q),
        .clock(s3_tq$clock)
    );
    texture_setup$s3_q s3_q(
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
    
endmodule // texture_setup


module texture_setup$a0_q(d,q,clock);
    
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
          
endmodule // texture_setup$a0_q


module texture_setup$a0_sq(d,q,clock);
    
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
          
endmodule // texture_setup$a0_sq


module texture_setup$a0_tq(d,q,clock);
    
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
          
endmodule // texture_setup$a0_tq


module texture_setup$acc(d,q,clock);
    
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
          
endmodule // texture_setup$acc


module texture_setup$busy(d,q,clock);
    
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
          
endmodule // texture_setup$busy


module texture_setup$d1$0(d,q,clock);
    
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
          
endmodule // texture_setup$d1$0


module texture_setup$d1$1(d,q,clock);
    
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
          
endmodule // texture_setup$d1$1


module texture_setup$d1$2(d,q,clock);
    
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
          
endmodule // texture_setup$d1$2


module texture_setup$d2$0(d,q,clock);
    
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
          
endmodule // texture_setup$d2$0


module texture_setup$d2$1(d,q,clock);
    
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
          
endmodule // texture_setup$d2$1


module texture_setup$d2$2(d,q,clock);
    
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
          
endmodule // texture_setup$d2$2


module texture_setup$done_r(d,q,clock);
    
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
          
endmodule // texture_setup$done_r


module texture_setup$e1x(d,q,clock);
    
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
          
endmodule // texture_setup$e1x


module texture_setup$e1y(d,q,clock);
    
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
          
endmodule // texture_setup$e1y


module texture_setup$e2x(d,q,clock);
    
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
          
endmodule // texture_setup$e2x


module texture_setup$e2y(d,q,clock);
    
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
          
endmodule // texture_setup$e2y


module texture_setup$exp(d,q,clock);
    
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
          
endmodule // texture_setup$exp


module texture_setup$g_q$0(d,q,clock);
    
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
          
endmodule // texture_setup$g_q$0


module texture_setup$g_q$1(d,q,clock);
    
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
          
endmodule // texture_setup$g_q$1


module texture_setup$g_sq$0(d,q,clock);
    
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
          
endmodule // texture_setup$g_sq$0


module texture_setup$g_sq$1(d,q,clock);
    
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
          
endmodule // texture_setup$g_sq$1


module texture_setup$g_tq$0(d,q,clock);
    
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
          
endmodule // texture_setup$g_tq$0


module texture_setup$g_tq$1(d,q,clock);
    
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
          
endmodule // texture_setup$g_tq$1


module texture_setup$lod_q$0(d,q,clock);
    
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
          
endmodule // texture_setup$lod_q$0


module texture_setup$lod_q$1(d,q,clock);
    
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
          
endmodule // texture_setup$lod_q$1


module texture_setup$lod_sq$0(d,q,clock);
    
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
          
endmodule // texture_setup$lod_sq$0


module texture_setup$lod_sq$1(d,q,clock);
    
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
          
endmodule // texture_setup$lod_sq$1


module texture_setup$lod_tq$0(d,q,clock);
    
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
          
endmodule // texture_setup$lod_tq$0


module texture_setup$lod_tq$1(d,q,clock);
    
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
          
endmodule // texture_setup$lod_tq$1


module texture_setup$mant(d,q,clock);
    
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
          
endmodule // texture_setup$mant


module texture_setup$mul(a,b,p);
    
    // Module arguments
    input wire  [47:0] a;
    input wire  [25:0] b;
    output reg  [73:0] p;
    
    // Update code (custom)
    // p = low 74 bits of a * b, both signed: a signed 74-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_setup$mul


module texture_setup$mul_q$0(a,b,p);
    
    // Module arguments
    input wire  [39:0] a;
    input wire  [17:0] b;
    output reg  [39:0] p;
    
    // Update code (custom)
    // p = low 40 bits of a * b, both signed: a signed 40-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_setup$mul_q$0


module texture_setup$mul_q$1(a,b,p);
    
    // Module arguments
    input wire  [39:0] a;
    input wire  [17:0] b;
    output reg  [39:0] p;
    
    // Update code (custom)
    // p = low 40 bits of a * b, both signed: a signed 40-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_setup$mul_q$1


module texture_setup$mul_sq$0(a,b,p);
    
    // Module arguments
    input wire  [46:0] a;
    input wire  [17:0] b;
    output reg  [46:0] p;
    
    // Update code (custom)
    // p = low 47 bits of a * b, both signed: a signed 47-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_setup$mul_sq$0


module texture_setup$mul_sq$1(a,b,p);
    
    // Module arguments
    input wire  [46:0] a;
    input wire  [17:0] b;
    output reg  [46:0] p;
    
    // Update code (custom)
    // p = low 47 bits of a * b, both signed: a signed 47-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_setup$mul_sq$1


module texture_setup$mul_tq$0(a,b,p);
    
    // Module arguments
    input wire  [46:0] a;
    input wire  [17:0] b;
    output reg  [46:0] p;
    
    // Update code (custom)
    // p = low 47 bits of a * b, both signed: a signed 47-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_setup$mul_tq$0


module texture_setup$mul_tq$1(a,b,p);
    
    // Module arguments
    input wire  [46:0] a;
    input wire  [17:0] b;
    output reg  [46:0] p;
    
    // Update code (custom)
    // p = low 47 bits of a * b, both signed: a signed 47-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_setup$mul_tq$1


module texture_setup$neg(d,q,clock);
    
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
          
endmodule // texture_setup$neg


module texture_setup$ox(d,q,clock);
    
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
          
endmodule // texture_setup$ox


module texture_setup$oy(d,q,clock);
    
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
          
endmodule // texture_setup$oy


module texture_setup$prod(d,q,clock);
    
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
          
endmodule // texture_setup$prod


module texture_setup$s1_valid(d,q,clock);
    
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
          
endmodule // texture_setup$s1_valid


module texture_setup$s1_x(d,q,clock);
    
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
          
endmodule // texture_setup$s1_x


module texture_setup$s1_y(d,q,clock);
    
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
          
endmodule // texture_setup$s1_y


module texture_setup$s2_q$0(d,q,clock);
    
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
          
endmodule // texture_setup$s2_q$0


module texture_setup$s2_q$1(d,q,clock);
    
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
          
endmodule // texture_setup$s2_q$1


module texture_setup$s2_sq$0(d,q,clock);
    
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
          
endmodule // texture_setup$s2_sq$0


module texture_setup$s2_sq$1(d,q,clock);
    
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
          
endmodule // texture_setup$s2_sq$1


module texture_setup$s2_tq$0(d,q,clock);
    
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
          
endmodule // texture_setup$s2_tq$0


module texture_setup$s2_tq$1(d,q,clock);
    
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
          
endmodule // texture_setup$s2_tq$1


module texture_setup$s2_valid(d,q,clock);
    
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
          
endmodule // texture_setup$s2_valid


module texture_setup$s3_q(d,q,clock);
    
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
          
endmodule // texture_setup$s3_q


module texture_setup$s3_sq(d,q,clock);
    
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
          
endmodule // texture_setup$s3_sq


module texture_setup$s3_tq(d,q,clock);
    
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
          
endmodule // texture_setup$s3_tq


module texture_setup$s3_valid(d,q,clock);
    
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
          
endmodule // texture_setup$s3_valid


module texture_setup$step(d,q,clock);
    
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
          
endmodule // texture_setup$step


module texture_setup$sx_d(x,y);
    
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
    
endmodule // texture_setup$sx_d


module texture_setup$sx_e1x(x,y);
    
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
    
endmodule // texture_setup$sx_e1x


module texture_setup$sx_e2x(x,y);
    
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
    
endmodule // texture_setup$sx_e2x


module texture_setup$sx_pos$0(x,y);
    
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
    
endmodule // texture_setup$sx_pos$0


module texture_setup$sx_pos$1(x,y);
    
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
    
endmodule // texture_setup$sx_pos$1


module texture_setup$sx_pos$2(x,y);
    
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
    
endmodule // texture_setup$sx_pos$2


module texture_setup$sx_pos$3(x,y);
    
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
    
endmodule // texture_setup$sx_pos$3


module texture_setup$sx_pos$4(x,y);
    
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
    
endmodule // texture_setup$sx_pos$4


module texture_setup$sx_pos$5(x,y);
    
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
    
endmodule // texture_setup$sx_pos$5


module texture_setup$sx_st$0(x,y);
    
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
    
endmodule // texture_setup$sx_st$0


module texture_setup$sx_st$1(x,y);
    
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
    
endmodule // texture_setup$sx_st$1


module texture_setup$sx_st$2(x,y);
    
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
    
endmodule // texture_setup$sx_st$2


module texture_setup$sx_st$3(x,y);
    
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
    
endmodule // texture_setup$sx_st$3


module texture_setup$sx_st$4(x,y);
    
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
    
endmodule // texture_setup$sx_st$4


module texture_setup$sx_st$5(x,y);
    
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
    
endmodule // texture_setup$sx_st$5
