

module vector(clock,width,height,inp$valid,inp$ready,inp$v0_x,inp$v0_y,inp$v0_z,inp$v0_c0,inp$v0_c1,inp$v0_c2,inp$v0_iw,inp$v1_x,inp$v1_y,inp$v1_z,inp$v1_c0,inp$v1_c1,inp$v1_c2,inp$v1_iw,inp$v2_x,inp$v2_y,inp$v2_z,inp$v2_c0,inp$v2_c1,inp$v2_c2,inp$v2_iw,inp$crosses,out_valid,out_ready,out_mask,out_x,out_y,out_z,out_rgb,idle);
    
    // Module arguments
    input wire  clock;
    input wire  [10:0] width;
    input wire  [10:0] height;
    input wire  inp$valid;
    output reg  inp$ready;
    input wire  [15:0] inp$v0_x;
    input wire  [15:0] inp$v0_y;
    input wire  [17:0] inp$v0_z;
    input wire  [7:0] inp$v0_c0;
    input wire  [7:0] inp$v0_c1;
    input wire  [7:0] inp$v0_c2;
    input wire  [15:0] inp$v0_iw;
    input wire  [15:0] inp$v1_x;
    input wire  [15:0] inp$v1_y;
    input wire  [17:0] inp$v1_z;
    input wire  [7:0] inp$v1_c0;
    input wire  [7:0] inp$v1_c1;
    input wire  [7:0] inp$v1_c2;
    input wire  [15:0] inp$v1_iw;
    input wire  [15:0] inp$v2_x;
    input wire  [15:0] inp$v2_y;
    input wire  [17:0] inp$v2_z;
    input wire  [7:0] inp$v2_c0;
    input wire  [7:0] inp$v2_c1;
    input wire  [7:0] inp$v2_c2;
    input wire  [15:0] inp$v2_iw;
    input wire  [5:0] inp$crosses;
    output reg  out_valid;
    input wire  out_ready;
    output reg  out_mask;
    output reg  [9:0] out_x;
    output reg  [9:0] out_y;
    output reg  [15:0] out_z;
    output reg  [23:0] out_rgb;
    output reg  idle;
    
    // Constant declarations
    localparam  at_mant = 8'h14;
    localparam  at_walk = 8'h14;
    localparam  drain = 8'h29;
    localparam  held_m1 = 8'h26;
    localparam  tap_exp = 8'h1;
    localparam  tap_z = 8'h2;
    localparam  tap_z0 = 8'h4;
    localparam  tap_c = 8'h24;
    localparam  tap_c0 = 8'h26;
    localparam  half_xy = 16'h8000;
    localparam  px_half_m1 = 17'b111;
    localparam  px_half = 17'b1000;
    localparam  frac = 8'h4;
    localparam  chunk = 10'b1111111111;
    localparam  chunk_p = 13'b1111111111111;
    localparam  lg = 8'h0;
    localparam  one_s = 8'h1;
    localparam  step = 10'b1;
    localparam  recip_n = 58'h100000000000000;
    localparam  y_shift = 8'ha;
    localparam  at_mask$0 = 1'b1;
    
    // Stub signals
    reg  lanes$0$clock;
    reg  lanes$0$run;
    reg  lanes$0$load;
    reg  [34:0] lanes$0$g_0;
    reg  [34:0] lanes$0$g_1;
    reg  [34:0] lanes$0$g_2;
    reg  lanes$0$valid;
    reg  [9:0] lanes$0$x;
    reg  [9:0] lanes$0$x0;
    reg  [9:0] lanes$0$x1;
    reg  [34:0] lanes$0$w_0;
    reg  [34:0] lanes$0$w_1;
    reg  [34:0] lanes$0$w_2;
    reg  lanes$0$owns_0;
    reg  lanes$0$owns_1;
    reg  lanes$0$owns_2;
    reg  [24:0] lanes$0$c_mant;
    reg  [7:0] lanes$0$c_exp;
    reg  [18:0] lanes$0$c_d1z;
    reg  [18:0] lanes$0$c_d2z;
    reg  [17:0] lanes$0$c_z0;
    reg  [15:0] lanes$0$c_iw_0;
    reg  [15:0] lanes$0$c_iw_1;
    reg  [15:0] lanes$0$c_iw_2;
    reg  [8:0] lanes$0$c_d1c_0;
    reg  [8:0] lanes$0$c_d1c_1;
    reg  [8:0] lanes$0$c_d1c_2;
    reg  [8:0] lanes$0$c_d2c_0;
    reg  [8:0] lanes$0$c_d2c_1;
    reg  [8:0] lanes$0$c_d2c_2;
    reg  [7:0] lanes$0$c_c0_0;
    reg  [7:0] lanes$0$c_c0_1;
    reg  [7:0] lanes$0$c_c0_2;
    wire  lanes$0$o_valid;
    wire  [15:0] lanes$0$o_z;
    wire  [23:0] lanes$0$o_rgb;
    reg  div_a$clock;
    reg  div_a$inp_valid;
    wire  div_a$inp_ready;
    reg  div_a$hold;
    reg  [57:0] div_a$inp_n;
    reg  [33:0] div_a$inp_d;
    wire  div_a$out_valid;
    reg  div_a$out_ready;
    wire  [25:0] div_a$out_q;
    wire  [33:0] div_a$out_r;
    reg  mul_s$0$clock;
    reg  mul_s$0$en;
    reg  [16:0] mul_s$0$a;
    reg  [16:0] mul_s$0$b;
    wire  [34:0] mul_s$0$p;
    reg  mul_s$1$clock;
    reg  mul_s$1$en;
    reg  [16:0] mul_s$1$a;
    reg  [16:0] mul_s$1$b;
    wire  [34:0] mul_s$1$p;
    reg  sbusy$d;
    wire  sbusy$q;
    reg  sbusy$clock;
    reg  [7:0] sc$d;
    wire  [7:0] sc$q;
    reg  sc$clock;
    reg  [7:0] dc$d;
    wire  [7:0] dc$q;
    reg  dc$clock;
    reg  [7:0] hold$0$d;
    wire  [7:0] hold$0$q;
    reg  hold$0$clock;
    reg  [7:0] hold$1$d;
    wire  [7:0] hold$1$q;
    reg  hold$1$clock;
    reg  sp$d;
    wire  sp$q;
    reg  sp$clock;
    reg  wp$d;
    wire  wp$q;
    reg  wp$clock;
    reg  [63:0] ph$d;
    wire  [63:0] ph$q;
    reg  ph$clock;
    reg  [15:0] vx$0$d;
    wire  [15:0] vx$0$q;
    reg  vx$0$clock;
    reg  [15:0] vx$1$d;
    wire  [15:0] vx$1$q;
    reg  vx$1$clock;
    reg  [15:0] vx$2$d;
    wire  [15:0] vx$2$q;
    reg  vx$2$clock;
    reg  [15:0] vy$0$d;
    wire  [15:0] vy$0$q;
    reg  vy$0$clock;
    reg  [15:0] vy$1$d;
    wire  [15:0] vy$1$q;
    reg  vy$1$clock;
    reg  [15:0] vy$2$d;
    wire  [15:0] vy$2$q;
    reg  vy$2$clock;
    reg  [17:0] vz$0$d;
    wire  [17:0] vz$0$q;
    reg  vz$0$clock;
    reg  [17:0] vz$1$d;
    wire  [17:0] vz$1$q;
    reg  vz$1$clock;
    reg  [17:0] vz$2$d;
    wire  [17:0] vz$2$q;
    reg  vz$2$clock;
    reg  [7:0] vc$0$d;
    wire  [7:0] vc$0$q;
    reg  vc$0$clock;
    reg  [7:0] vc$1$d;
    wire  [7:0] vc$1$q;
    reg  vc$1$clock;
    reg  [7:0] vc$2$d;
    wire  [7:0] vc$2$q;
    reg  vc$2$clock;
    reg  [7:0] vc$3$d;
    wire  [7:0] vc$3$q;
    reg  vc$3$clock;
    reg  [7:0] vc$4$d;
    wire  [7:0] vc$4$q;
    reg  vc$4$clock;
    reg  [7:0] vc$5$d;
    wire  [7:0] vc$5$q;
    reg  vc$5$clock;
    reg  [7:0] vc$6$d;
    wire  [7:0] vc$6$q;
    reg  vc$6$clock;
    reg  [7:0] vc$7$d;
    wire  [7:0] vc$7$q;
    reg  vc$7$clock;
    reg  [7:0] vc$8$d;
    wire  [7:0] vc$8$q;
    reg  vc$8$clock;
    reg  [15:0] viw$0$d;
    wire  [15:0] viw$0$q;
    reg  viw$0$clock;
    reg  [15:0] viw$1$d;
    wire  [15:0] viw$1$q;
    reg  viw$1$clock;
    reg  [15:0] viw$2$d;
    wire  [15:0] viw$2$q;
    reg  viw$2$clock;
    reg  [15:0] ex$0$x;
    wire  [16:0] ex$0$y;
    reg  [15:0] ex$1$x;
    wire  [16:0] ex$1$y;
    reg  [15:0] ex$2$x;
    wire  [16:0] ex$2$y;
    reg  [15:0] ey$0$x;
    wire  [16:0] ey$0$y;
    reg  [15:0] ey$1$x;
    wire  [16:0] ey$1$y;
    reg  [15:0] ey$2$x;
    wire  [16:0] ey$2$y;
    reg  [17:0] ez$0$x;
    wire  [18:0] ez$0$y;
    reg  [17:0] ez$1$x;
    wire  [18:0] ez$1$y;
    reg  [17:0] ez$2$x;
    wire  [18:0] ez$2$y;
    reg  [15:0] min_xr$d;
    wire  [15:0] min_xr$q;
    reg  min_xr$clock;
    reg  [15:0] max_xr$d;
    wire  [15:0] max_xr$q;
    reg  max_xr$clock;
    reg  [15:0] min_yr$d;
    wire  [15:0] min_yr$q;
    reg  min_yr$clock;
    reg  [15:0] max_yr$d;
    wire  [15:0] max_yr$q;
    reg  max_yr$clock;
    reg  [15:0] top_xr$d;
    wire  [15:0] top_xr$q;
    reg  top_xr$clock;
    reg  [16:0] neg_lo_x$x;
    wire  neg_lo_x$neg;
    reg  [16:0] neg_lo_y$x;
    wire  neg_lo_y$neg;
    reg  [16:0] neg_hi_x$x;
    wire  neg_hi_x$neg;
    reg  [16:0] neg_hi_y$x;
    wire  neg_hi_y$neg;
    reg  [15:0] ext_min_x$x;
    wire  [16:0] ext_min_x$y;
    reg  [15:0] ext_min_y$x;
    wire  [16:0] ext_min_y$y;
    reg  [15:0] ext_max_x$x;
    wire  [16:0] ext_max_x$y;
    reg  [15:0] ext_max_y$x;
    wire  [16:0] ext_max_y$y;
    reg  [15:0] ext_top$x;
    wire  [16:0] ext_top$y;
    reg  [15:0] neg_top$x;
    wire  neg_top$neg;
    reg  [12:0] bx0$d;
    wire  [12:0] bx0$q;
    reg  bx0$clock;
    reg  [12:0] bx1$d;
    wire  [12:0] bx1$q;
    reg  bx1$clock;
    reg  [12:0] by0$d;
    wire  [12:0] by0$q;
    reg  by0$clock;
    reg  [12:0] by1$d;
    wire  [12:0] by1$q;
    reg  by1$clock;
    reg  bneg$d;
    wire  bneg$q;
    reg  bneg$clock;
    reg  empty$d;
    wire  empty$q;
    reg  empty$clock;
    reg  [12:0] cs$d;
    wire  [12:0] cs$q;
    reg  cs$clock;
    reg  [34:0] area$d;
    wire  [34:0] area$q;
    reg  area$clock;
    reg  [34:0] area_neg$x;
    wire  area_neg$neg;
    reg  [33:0] area_abs$d;
    wire  [33:0] area_abs$q;
    reg  area_abs$clock;
    reg  [33:0] lead_a$x;
    wire  [7:0] lead_a$pos;
    reg  [7:0] exp_a$d;
    wire  [7:0] exp_a$q;
    reg  exp_a$clock;
    reg  [33:0] norm_a$x;
    reg  [7:0] norm_a$exp;
    wire  [33:0] norm_a$d;
    reg  [33:0] div_da$d;
    wire  [33:0] div_da$q;
    reg  div_da$clock;
    reg  [24:0] mant$d;
    wire  [24:0] mant$q;
    reg  mant$clock;
    reg  [16:0] dx$0$d;
    wire  [16:0] dx$0$q;
    reg  dx$0$clock;
    reg  [16:0] dx$1$d;
    wire  [16:0] dx$1$q;
    reg  dx$1$clock;
    reg  [16:0] dx$2$d;
    wire  [16:0] dx$2$q;
    reg  dx$2$clock;
    reg  [16:0] dy$0$d;
    wire  [16:0] dy$0$q;
    reg  dy$0$clock;
    reg  [16:0] dy$1$d;
    wire  [16:0] dy$1$q;
    reg  dy$1$clock;
    reg  [16:0] dy$2$d;
    wire  [16:0] dy$2$q;
    reg  dy$2$clock;
    reg  [34:0] w0$0$d;
    wire  [34:0] w0$0$q;
    reg  w0$0$clock;
    reg  [34:0] w0$1$d;
    wire  [34:0] w0$1$q;
    reg  w0$1$clock;
    reg  [34:0] w0$2$d;
    wire  [34:0] w0$2$q;
    reg  w0$2$clock;
    reg  [18:0] d1z$d;
    wire  [18:0] d1z$q;
    reg  d1z$clock;
    reg  [18:0] d2z$d;
    wire  [18:0] d2z$q;
    reg  d2z$clock;
    reg  [8:0] d1c$0$d;
    wire  [8:0] d1c$0$q;
    reg  d1c$0$clock;
    reg  [8:0] d1c$1$d;
    wire  [8:0] d1c$1$q;
    reg  d1c$1$clock;
    reg  [8:0] d1c$2$d;
    wire  [8:0] d1c$2$q;
    reg  d1c$2$clock;
    reg  [8:0] d2c$0$d;
    wire  [8:0] d2c$0$q;
    reg  d2c$0$clock;
    reg  [8:0] d2c$1$d;
    wire  [8:0] d2c$1$q;
    reg  d2c$1$clock;
    reg  [8:0] d2c$2$d;
    wire  [8:0] d2c$2$q;
    reg  d2c$2$clock;
    reg  sv$d;
    wire  sv$q;
    reg  sv$clock;
    reg  [9:0] sy$d;
    wire  [9:0] sy$q;
    reg  sy$clock;
    reg  [9:0] sy1$d;
    wire  [9:0] sy1$q;
    reg  sy1$clock;
    reg  [9:0] sc0$d;
    wire  [9:0] sc0$q;
    reg  sc0$clock;
    reg  [9:0] sc1$d;
    wire  [9:0] sc1$q;
    reg  sc1$clock;
    reg  [9:0] sx0$d;
    wire  [9:0] sx0$q;
    reg  sx0$clock;
    reg  [9:0] sx1$d;
    wire  [9:0] sx1$q;
    reg  sx1$clock;
    reg  [9:0] sl$d;
    wire  [9:0] sl$q;
    reg  sl$clock;
    reg  [9:0] sr$d;
    wire  [9:0] sr$q;
    reg  sr$clock;
    reg  [34:0] el$0$d;
    wire  [34:0] el$0$q;
    reg  el$0$clock;
    reg  [34:0] el$1$d;
    wire  [34:0] el$1$q;
    reg  el$1$clock;
    reg  [34:0] el$2$d;
    wire  [34:0] el$2$q;
    reg  el$2$clock;
    reg  [34:0] er$0$d;
    wire  [34:0] er$0$q;
    reg  er$0$clock;
    reg  [34:0] er$1$d;
    wire  [34:0] er$1$q;
    reg  er$1$clock;
    reg  [34:0] er$2$d;
    wire  [34:0] er$2$q;
    reg  er$2$clock;
    reg  [16:0] sdx$0$d;
    wire  [16:0] sdx$0$q;
    reg  sdx$0$clock;
    reg  [16:0] sdx$1$d;
    wire  [16:0] sdx$1$q;
    reg  sdx$1$clock;
    reg  [16:0] sdx$2$d;
    wire  [16:0] sdx$2$q;
    reg  sdx$2$clock;
    reg  [16:0] sdy$0$d;
    wire  [16:0] sdy$0$q;
    reg  sdy$0$clock;
    reg  [16:0] sdy$1$d;
    wire  [16:0] sdy$1$q;
    reg  sdy$1$clock;
    reg  [16:0] sdy$2$d;
    wire  [16:0] sdy$2$q;
    reg  sdy$2$clock;
    reg  [16:0] scls$0$dx;
    reg  [16:0] scls$0$dy;
    wire  scls$0$left;
    wire  scls$0$right;
    wire  scls$0$flat;
    wire  scls$0$owns;
    wire  [34:0] scls$0$g;
    wire  [34:0] scls$0$h;
    reg  [16:0] scls$1$dx;
    reg  [16:0] scls$1$dy;
    wire  scls$1$left;
    wire  scls$1$right;
    wire  scls$1$flat;
    wire  scls$1$owns;
    wire  [34:0] scls$1$g;
    wire  [34:0] scls$1$h;
    reg  [16:0] scls$2$dx;
    reg  [16:0] scls$2$dy;
    wire  scls$2$left;
    wire  scls$2$right;
    wire  scls$2$flat;
    wire  scls$2$owns;
    wire  [34:0] scls$2$g;
    wire  [34:0] scls$2$h;
    reg  [34:0] rej_ll$0$e;
    reg  rej_ll$0$owns;
    wire  rej_ll$0$rejects;
    reg  [34:0] rej_ll$1$e;
    reg  rej_ll$1$owns;
    wire  rej_ll$1$rejects;
    reg  [34:0] rej_ll$2$e;
    reg  rej_ll$2$owns;
    wire  rej_ll$2$rejects;
    reg  [34:0] rej_lm$0$e;
    reg  rej_lm$0$owns;
    wire  rej_lm$0$rejects;
    reg  [34:0] rej_lm$1$e;
    reg  rej_lm$1$owns;
    wire  rej_lm$1$rejects;
    reg  [34:0] rej_lm$2$e;
    reg  rej_lm$2$owns;
    wire  rej_lm$2$rejects;
    reg  [34:0] rej_lf$0$e;
    reg  rej_lf$0$owns;
    wire  rej_lf$0$rejects;
    reg  [34:0] rej_lf$1$e;
    reg  rej_lf$1$owns;
    wire  rej_lf$1$rejects;
    reg  [34:0] rej_lf$2$e;
    reg  rej_lf$2$owns;
    wire  rej_lf$2$rejects;
    reg  [34:0] rej_rf$0$e;
    reg  rej_rf$0$owns;
    wire  rej_rf$0$rejects;
    reg  [34:0] rej_rf$1$e;
    reg  rej_rf$1$owns;
    wire  rej_rf$1$rejects;
    reg  [34:0] rej_rf$2$e;
    reg  rej_rf$2$owns;
    wire  rej_rf$2$rejects;
    reg  [34:0] rej_rn$0$e;
    reg  rej_rn$0$owns;
    wire  rej_rn$0$rejects;
    reg  [34:0] rej_rn$1$e;
    reg  rej_rn$1$owns;
    wire  rej_rn$1$rejects;
    reg  [34:0] rej_rn$2$e;
    reg  rej_rn$2$owns;
    wire  rej_rn$2$rejects;
    reg  tv$d;
    wire  tv$q;
    reg  tv$clock;
    reg  [9:0] tx$d;
    wire  [9:0] tx$q;
    reg  tx$clock;
    reg  [9:0] te$d;
    wire  [9:0] te$q;
    reg  te$clock;
    reg  [9:0] ty$d;
    wire  [9:0] ty$q;
    reg  ty$clock;
    reg  [9:0] wx0$d;
    wire  [9:0] wx0$q;
    reg  wx0$clock;
    reg  [9:0] wx1$d;
    wire  [9:0] wx1$q;
    reg  wx1$clock;
    reg  [34:0] w$0$d;
    wire  [34:0] w$0$q;
    reg  w$0$clock;
    reg  [34:0] w$1$d;
    wire  [34:0] w$1$q;
    reg  w$1$clock;
    reg  [34:0] w$2$d;
    wire  [34:0] w$2$q;
    reg  w$2$clock;
    reg  wown$0$d;
    wire  wown$0$q;
    reg  wown$0$clock;
    reg  wown$1$d;
    wire  wown$1$q;
    reg  wown$1$clock;
    reg  wown$2$d;
    wire  wown$2$q;
    reg  wown$2$clock;
    reg  [34:0] wstep$0$d;
    wire  [34:0] wstep$0$q;
    reg  wstep$0$clock;
    reg  [34:0] wstep$1$d;
    wire  [34:0] wstep$1$q;
    reg  wstep$1$clock;
    reg  [34:0] wstep$2$d;
    wire  [34:0] wstep$2$q;
    reg  wstep$2$clock;
    reg  [24:0] k_mant$0$d;
    wire  [24:0] k_mant$0$q;
    reg  k_mant$0$clock;
    reg  [24:0] k_mant$1$d;
    wire  [24:0] k_mant$1$q;
    reg  k_mant$1$clock;
    reg  [7:0] k_exp$0$d;
    wire  [7:0] k_exp$0$q;
    reg  k_exp$0$clock;
    reg  [7:0] k_exp$1$d;
    wire  [7:0] k_exp$1$q;
    reg  k_exp$1$clock;
    reg  [18:0] k_d1z$0$d;
    wire  [18:0] k_d1z$0$q;
    reg  k_d1z$0$clock;
    reg  [18:0] k_d1z$1$d;
    wire  [18:0] k_d1z$1$q;
    reg  k_d1z$1$clock;
    reg  [18:0] k_d2z$0$d;
    wire  [18:0] k_d2z$0$q;
    reg  k_d2z$0$clock;
    reg  [18:0] k_d2z$1$d;
    wire  [18:0] k_d2z$1$q;
    reg  k_d2z$1$clock;
    reg  [17:0] k_z0$0$d;
    wire  [17:0] k_z0$0$q;
    reg  k_z0$0$clock;
    reg  [17:0] k_z0$1$d;
    wire  [17:0] k_z0$1$q;
    reg  k_z0$1$clock;
    reg  [15:0] k_iw$0$d;
    wire  [15:0] k_iw$0$q;
    reg  k_iw$0$clock;
    reg  [15:0] k_iw$1$d;
    wire  [15:0] k_iw$1$q;
    reg  k_iw$1$clock;
    reg  [15:0] k_iw$2$d;
    wire  [15:0] k_iw$2$q;
    reg  k_iw$2$clock;
    reg  [15:0] k_iw$3$d;
    wire  [15:0] k_iw$3$q;
    reg  k_iw$3$clock;
    reg  [15:0] k_iw$4$d;
    wire  [15:0] k_iw$4$q;
    reg  k_iw$4$clock;
    reg  [15:0] k_iw$5$d;
    wire  [15:0] k_iw$5$q;
    reg  k_iw$5$clock;
    reg  [8:0] k_d1c$0$d;
    wire  [8:0] k_d1c$0$q;
    reg  k_d1c$0$clock;
    reg  [8:0] k_d1c$1$d;
    wire  [8:0] k_d1c$1$q;
    reg  k_d1c$1$clock;
    reg  [8:0] k_d1c$2$d;
    wire  [8:0] k_d1c$2$q;
    reg  k_d1c$2$clock;
    reg  [8:0] k_d1c$3$d;
    wire  [8:0] k_d1c$3$q;
    reg  k_d1c$3$clock;
    reg  [8:0] k_d1c$4$d;
    wire  [8:0] k_d1c$4$q;
    reg  k_d1c$4$clock;
    reg  [8:0] k_d1c$5$d;
    wire  [8:0] k_d1c$5$q;
    reg  k_d1c$5$clock;
    reg  [8:0] k_d2c$0$d;
    wire  [8:0] k_d2c$0$q;
    reg  k_d2c$0$clock;
    reg  [8:0] k_d2c$1$d;
    wire  [8:0] k_d2c$1$q;
    reg  k_d2c$1$clock;
    reg  [8:0] k_d2c$2$d;
    wire  [8:0] k_d2c$2$q;
    reg  k_d2c$2$clock;
    reg  [8:0] k_d2c$3$d;
    wire  [8:0] k_d2c$3$q;
    reg  k_d2c$3$clock;
    reg  [8:0] k_d2c$4$d;
    wire  [8:0] k_d2c$4$q;
    reg  k_d2c$4$clock;
    reg  [8:0] k_d2c$5$d;
    wire  [8:0] k_d2c$5$q;
    reg  k_d2c$5$clock;
    reg  [7:0] k_c0$0$d;
    wire  [7:0] k_c0$0$q;
    reg  k_c0$0$clock;
    reg  [7:0] k_c0$1$d;
    wire  [7:0] k_c0$1$q;
    reg  k_c0$1$clock;
    reg  [7:0] k_c0$2$d;
    wire  [7:0] k_c0$2$q;
    reg  k_c0$2$clock;
    reg  [7:0] k_c0$3$d;
    wire  [7:0] k_c0$3$q;
    reg  k_c0$3$clock;
    reg  [7:0] k_c0$4$d;
    wire  [7:0] k_c0$4$q;
    reg  k_c0$4$clock;
    reg  [7:0] k_c0$5$d;
    wire  [7:0] k_c0$5$q;
    reg  k_c0$5$clock;
    reg  tag_dl$clock;
    reg  tag_dl$en;
    reg  [19:0] tag_dl$d;
    wire  [19:0] tag_dl$q;
    reg  [9:0] o_x$d;
    wire  [9:0] o_x$q;
    reg  o_x$clock;
    reg  [9:0] o_y$d;
    wire  [9:0] o_y$q;
    reg  o_y$clock;
    reg  [15:0] place_z$0$x;
    wire  [15:0] place_z$0$y;
    reg  [23:0] place_rgb$0$x;
    wire  [23:0] place_rgb$0$y;
    
    // Local signals
    reg  run;
    reg  take;
    reg  set_ok;
    reg  hand;
    reg  [15:0] ux$0;
    reg  [15:0] ux$1;
    reg  [15:0] ux$2;
    reg  [15:0] uy$0;
    reg  [15:0] uy$1;
    reg  [15:0] uy$2;
    reg  [15:0] min_x;
    reg  [15:0] max_x;
    reg  [15:0] min_y;
    reg  [15:0] max_y;
    reg  [15:0] top_x;
    reg  [16:0] lo_x;
    reg  [16:0] lo_y;
    reg  [16:0] hi_x;
    reg  [16:0] hi_y;
    reg  [12:0] hi_x_c;
    reg  [12:0] hi_y_c;
    reg  [12:0] top_c;
    reg  [16:0] cx0;
    reg  [16:0] cy0;
    reg  [24:0] mant_c;
    reg  [34:0] s_chunk$0;
    reg  [34:0] s_chunk$1;
    reg  [34:0] s_chunk$2;
    reg  [34:0] s_less$0;
    reg  [34:0] s_less$1;
    reg  [34:0] s_less$2;
    reg  out_l;
    reg  out_lm;
    reg  out_r;
    reg  out_rn;
    reg  dead;
    reg  l_right;
    reg  l_left;
    reg  r_left;
    reg  r_right;
    reg  found;
    reg  row_empty;
    reg  row_last;
    reg  walk_free;
    reg  [24:0] c_mant;
    reg  [7:0] c_exp;
    reg  [18:0] c_d1z;
    reg  [18:0] c_d2z;
    reg  [17:0] c_z0;
    reg  [15:0] c_iw$0;
    reg  [15:0] c_iw$1;
    reg  [15:0] c_iw$2;
    reg  [8:0] c_d1c$0;
    reg  [8:0] c_d1c$1;
    reg  [8:0] c_d1c$2;
    reg  [8:0] c_d2c$0;
    reg  [8:0] c_d2c$1;
    reg  [8:0] c_d2c$2;
    reg  [7:0] c_c0$0;
    reg  [7:0] c_c0$1;
    reg  [7:0] c_c0$2;
    reg  [19:0] tag;
    reg  g_mask$0;
    reg  g_mask$1;
    reg  [15:0] g_z$0;
    reg  [15:0] g_z$1;
    reg  [23:0] g_rgb$0;
    reg  [23:0] g_rgb$1;
    
    // Sub module instances
    vector$lanes$0 lanes$0(
        .clock(lanes$0$clock),
        .run(lanes$0$run),
        .load(lanes$0$load),
        .g_0(lanes$0$g_0),
        .g_1(lanes$0$g_1),
        .g_2(lanes$0$g_2),
        .valid(lanes$0$valid),
        .x(lanes$0$x),
        .x0(lanes$0$x0),
        .x1(lanes$0$x1),
        .w_0(lanes$0$w_0),
        .w_1(lanes$0$w_1),
        .w_2(lanes$0$w_2),
        .owns_0(lanes$0$owns_0),
        .owns_1(lanes$0$owns_1),
        .owns_2(lanes$0$owns_2),
        .c_mant(lanes$0$c_mant),
        .c_exp(lanes$0$c_exp),
        .c_d1z(lanes$0$c_d1z),
        .c_d2z(lanes$0$c_d2z),
        .c_z0(lanes$0$c_z0),
        .c_iw_0(lanes$0$c_iw_0),
        .c_iw_1(lanes$0$c_iw_1),
        .c_iw_2(lanes$0$c_iw_2),
        .c_d1c_0(lanes$0$c_d1c_0),
        .c_d1c_1(lanes$0$c_d1c_1),
        .c_d1c_2(lanes$0$c_d1c_2),
        .c_d2c_0(lanes$0$c_d2c_0),
        .c_d2c_1(lanes$0$c_d2c_1),
        .c_d2c_2(lanes$0$c_d2c_2),
        .c_c0_0(lanes$0$c_c0_0),
        .c_c0_1(lanes$0$c_c0_1),
        .c_c0_2(lanes$0$c_c0_2),
        .o_valid(lanes$0$o_valid),
        .o_z(lanes$0$o_z),
        .o_rgb(lanes$0$o_rgb)
    );
    vector$div_a div_a(
        .clock(div_a$clock),
        .inp_valid(div_a$inp_valid),
        .inp_ready(div_a$inp_ready),
        .hold(div_a$hold),
        .inp_n(div_a$inp_n),
        .inp_d(div_a$inp_d),
        .out_valid(div_a$out_valid),
        .out_ready(div_a$out_ready),
        .out_q(div_a$out_q),
        .out_r(div_a$out_r)
    );
    vector$mul_s$0 mul_s$0(
        .clock(mul_s$0$clock),
        .en(mul_s$0$en),
        .a(mul_s$0$a),
        .b(mul_s$0$b),
        .p(mul_s$0$p)
    );
    vector$mul_s$1 mul_s$1(
        .clock(mul_s$1$clock),
        .en(mul_s$1$en),
        .a(mul_s$1$a),
        .b(mul_s$1$b),
        .p(mul_s$1$p)
    );
    vector$sbusy sbusy(
        .d(sbusy$d),
        .q(sbusy$q),
        .clock(sbusy$clock)
    );
    vector$sc sc(
        .d(sc$d),
        .q(sc$q),
        .clock(sc$clock)
    );
    vector$dc dc(
        .d(dc$d),
        .q(dc$q),
        .clock(dc$clock)
    );
    vector$hold$0 hold$0(
        .d(hold$0$d),
        .q(hold$0$q),
        .clock(hold$0$clock)
    );
    vector$hold$1 hold$1(
        .d(hold$1$d),
        .q(hold$1$q),
        .clock(hold$1$clock)
    );
    vector$sp sp(
        .d(sp$d),
        .q(sp$q),
        .clock(sp$clock)
    );
    vector$wp wp(
        .d(wp$d),
        .q(wp$q),
        .clock(wp$clock)
    );
    vector$ph ph(
        .d(ph$d),
        .q(ph$q),
        .clock(ph$clock)
    );
    vector$vx$0 vx$0(
        .d(vx$0$d),
        .q(vx$0$q),
        .clock(vx$0$clock)
    );
    vector$vx$1 vx$1(
        .d(vx$1$d),
        .q(vx$1$q),
        .clock(vx$1$clock)
    );
    vector$vx$2 vx$2(
        .d(vx$2$d),
        .q(vx$2$q),
        .clock(vx$2$clock)
    );
    vector$vy$0 vy$0(
        .d(vy$0$d),
        .q(vy$0$q),
        .clock(vy$0$clock)
    );
    vector$vy$1 vy$1(
        .d(vy$1$d),
        .q(vy$1$q),
        .clock(vy$1$clock)
    );
    vector$vy$2 vy$2(
        .d(vy$2$d),
        .q(vy$2$q),
        .clock(vy$2$clock)
    );
    vector$vz$0 vz$0(
        .d(vz$0$d),
        .q(vz$0$q),
        .clock(vz$0$clock)
    );
    vector$vz$1 vz$1(
        .d(vz$1$d),
        .q(vz$1$q),
        .clock(vz$1$clock)
    );
    vector$vz$2 vz$2(
        .d(vz$2$d),
        .q(vz$2$q),
        .clock(vz$2$clock)
    );
    vector$vc$0 vc$0(
        .d(vc$0$d),
        .q(vc$0$q),
        .clock(vc$0$clock)
    );
    vector$vc$1 vc$1(
        .d(vc$1$d),
        .q(vc$1$q),
        .clock(vc$1$clock)
    );
    vector$vc$2 vc$2(
        .d(vc$2$d),
        .q(vc$2$q),
        .clock(vc$2$clock)
    );
    vector$vc$3 vc$3(
        .d(vc$3$d),
        .q(vc$3$q),
        .clock(vc$3$clock)
    );
    vector$vc$4 vc$4(
        .d(vc$4$d),
        .q(vc$4$q),
        .clock(vc$4$clock)
    );
    vector$vc$5 vc$5(
        .d(vc$5$d),
        .q(vc$5$q),
        .clock(vc$5$clock)
    );
    vector$vc$6 vc$6(
        .d(vc$6$d),
        .q(vc$6$q),
        .clock(vc$6$clock)
    );
    vector$vc$7 vc$7(
        .d(vc$7$d),
        .q(vc$7$q),
        .clock(vc$7$clock)
    );
    vector$vc$8 vc$8(
        .d(vc$8$d),
        .q(vc$8$q),
        .clock(vc$8$clock)
    );
    vector$viw$0 viw$0(
        .d(viw$0$d),
        .q(viw$0$q),
        .clock(viw$0$clock)
    );
    vector$viw$1 viw$1(
        .d(viw$1$d),
        .q(viw$1$q),
        .clock(viw$1$clock)
    );
    vector$viw$2 viw$2(
        .d(viw$2$d),
        .q(viw$2$q),
        .clock(viw$2$clock)
    );
    vector$ex$0 ex$0(
        .x(ex$0$x),
        .y(ex$0$y)
    );
    vector$ex$1 ex$1(
        .x(ex$1$x),
        .y(ex$1$y)
    );
    vector$ex$2 ex$2(
        .x(ex$2$x),
        .y(ex$2$y)
    );
    vector$ey$0 ey$0(
        .x(ey$0$x),
        .y(ey$0$y)
    );
    vector$ey$1 ey$1(
        .x(ey$1$x),
        .y(ey$1$y)
    );
    vector$ey$2 ey$2(
        .x(ey$2$x),
        .y(ey$2$y)
    );
    vector$ez$0 ez$0(
        .x(ez$0$x),
        .y(ez$0$y)
    );
    vector$ez$1 ez$1(
        .x(ez$1$x),
        .y(ez$1$y)
    );
    vector$ez$2 ez$2(
        .x(ez$2$x),
        .y(ez$2$y)
    );
    vector$min_xr min_xr(
        .d(min_xr$d),
        .q(min_xr$q),
        .clock(min_xr$clock)
    );
    vector$max_xr max_xr(
        .d(max_xr$d),
        .q(max_xr$q),
        .clock(max_xr$clock)
    );
    vector$min_yr min_yr(
        .d(min_yr$d),
        .q(min_yr$q),
        .clock(min_yr$clock)
    );
    vector$max_yr max_yr(
        .d(max_yr$d),
        .q(max_yr$q),
        .clock(max_yr$clock)
    );
    vector$top_xr top_xr(
        .d(top_xr$d),
        .q(top_xr$q),
        .clock(top_xr$clock)
    );
    vector$neg_lo_x neg_lo_x(
        .x(neg_lo_x$x),
        .neg(neg_lo_x$neg)
    );
    vector$neg_lo_y neg_lo_y(
        .x(neg_lo_y$x),
        .neg(neg_lo_y$neg)
    );
    vector$neg_hi_x neg_hi_x(
        .x(neg_hi_x$x),
        .neg(neg_hi_x$neg)
    );
    vector$neg_hi_y neg_hi_y(
        .x(neg_hi_y$x),
        .neg(neg_hi_y$neg)
    );
    vector$ext_min_x ext_min_x(
        .x(ext_min_x$x),
        .y(ext_min_x$y)
    );
    vector$ext_min_y ext_min_y(
        .x(ext_min_y$x),
        .y(ext_min_y$y)
    );
    vector$ext_max_x ext_max_x(
        .x(ext_max_x$x),
        .y(ext_max_x$y)
    );
    vector$ext_max_y ext_max_y(
        .x(ext_max_y$x),
        .y(ext_max_y$y)
    );
    vector$ext_top ext_top(
        .x(ext_top$x),
        .y(ext_top$y)
    );
    vector$neg_top neg_top(
        .x(neg_top$x),
        .neg(neg_top$neg)
    );
    vector$bx0 bx0(
        .d(bx0$d),
        .q(bx0$q),
        .clock(bx0$clock)
    );
    vector$bx1 bx1(
        .d(bx1$d),
        .q(bx1$q),
        .clock(bx1$clock)
    );
    vector$by0 by0(
        .d(by0$d),
        .q(by0$q),
        .clock(by0$clock)
    );
    vector$by1 by1(
        .d(by1$d),
        .q(by1$q),
        .clock(by1$clock)
    );
    vector$bneg bneg(
        .d(bneg$d),
        .q(bneg$q),
        .clock(bneg$clock)
    );
    vector$empty empty(
        .d(empty$d),
        .q(empty$q),
        .clock(empty$clock)
    );
    vector$cs cs(
        .d(cs$d),
        .q(cs$q),
        .clock(cs$clock)
    );
    vector$area area(
        .d(area$d),
        .q(area$q),
        .clock(area$clock)
    );
    vector$area_neg area_neg(
        .x(area_neg$x),
        .neg(area_neg$neg)
    );
    vector$area_abs area_abs(
        .d(area_abs$d),
        .q(area_abs$q),
        .clock(area_abs$clock)
    );
    vector$lead_a lead_a(
        .x(lead_a$x),
        .pos(lead_a$pos)
    );
    vector$exp_a exp_a(
        .d(exp_a$d),
        .q(exp_a$q),
        .clock(exp_a$clock)
    );
    vector$norm_a norm_a(
        .x(norm_a$x),
        .exp(norm_a$exp),
        .d(norm_a$d)
    );
    vector$div_da div_da(
        .d(div_da$d),
        .q(div_da$q),
        .clock(div_da$clock)
    );
    vector$mant mant(
        .d(mant$d),
        .q(mant$q),
        .clock(mant$clock)
    );
    vector$dx$0 dx$0(
        .d(dx$0$d),
        .q(dx$0$q),
        .clock(dx$0$clock)
    );
    vector$dx$1 dx$1(
        .d(dx$1$d),
        .q(dx$1$q),
        .clock(dx$1$clock)
    );
    vector$dx$2 dx$2(
        .d(dx$2$d),
        .q(dx$2$q),
        .clock(dx$2$clock)
    );
    vector$dy$0 dy$0(
        .d(dy$0$d),
        .q(dy$0$q),
        .clock(dy$0$clock)
    );
    vector$dy$1 dy$1(
        .d(dy$1$d),
        .q(dy$1$q),
        .clock(dy$1$clock)
    );
    vector$dy$2 dy$2(
        .d(dy$2$d),
        .q(dy$2$q),
        .clock(dy$2$clock)
    );
    vector$w0$0 w0$0(
        .d(w0$0$d),
        .q(w0$0$q),
        .clock(w0$0$clock)
    );
    vector$w0$1 w0$1(
        .d(w0$1$d),
        .q(w0$1$q),
        .clock(w0$1$clock)
    );
    vector$w0$2 w0$2(
        .d(w0$2$d),
        .q(w0$2$q),
        .clock(w0$2$clock)
    );
    vector$d1z d1z(
        .d(d1z$d),
        .q(d1z$q),
        .clock(d1z$clock)
    );
    vector$d2z d2z(
        .d(d2z$d),
        .q(d2z$q),
        .clock(d2z$clock)
    );
    vector$d1c$0 d1c$0(
        .d(d1c$0$d),
        .q(d1c$0$q),
        .clock(d1c$0$clock)
    );
    vector$d1c$1 d1c$1(
        .d(d1c$1$d),
        .q(d1c$1$q),
        .clock(d1c$1$clock)
    );
    vector$d1c$2 d1c$2(
        .d(d1c$2$d),
        .q(d1c$2$q),
        .clock(d1c$2$clock)
    );
    vector$d2c$0 d2c$0(
        .d(d2c$0$d),
        .q(d2c$0$q),
        .clock(d2c$0$clock)
    );
    vector$d2c$1 d2c$1(
        .d(d2c$1$d),
        .q(d2c$1$q),
        .clock(d2c$1$clock)
    );
    vector$d2c$2 d2c$2(
        .d(d2c$2$d),
        .q(d2c$2$q),
        .clock(d2c$2$clock)
    );
    vector$sv sv(
        .d(sv$d),
        .q(sv$q),
        .clock(sv$clock)
    );
    vector$sy sy(
        .d(sy$d),
        .q(sy$q),
        .clock(sy$clock)
    );
    vector$sy1 sy1(
        .d(sy1$d),
        .q(sy1$q),
        .clock(sy1$clock)
    );
    vector$sc0 sc0(
        .d(sc0$d),
        .q(sc0$q),
        .clock(sc0$clock)
    );
    vector$sc1 sc1(
        .d(sc1$d),
        .q(sc1$q),
        .clock(sc1$clock)
    );
    vector$sx0 sx0(
        .d(sx0$d),
        .q(sx0$q),
        .clock(sx0$clock)
    );
    vector$sx1 sx1(
        .d(sx1$d),
        .q(sx1$q),
        .clock(sx1$clock)
    );
    vector$sl sl(
        .d(sl$d),
        .q(sl$q),
        .clock(sl$clock)
    );
    vector$sr sr(
        .d(sr$d),
        .q(sr$q),
        .clock(sr$clock)
    );
    vector$el$0 el$0(
        .d(el$0$d),
        .q(el$0$q),
        .clock(el$0$clock)
    );
    vector$el$1 el$1(
        .d(el$1$d),
        .q(el$1$q),
        .clock(el$1$clock)
    );
    vector$el$2 el$2(
        .d(el$2$d),
        .q(el$2$q),
        .clock(el$2$clock)
    );
    vector$er$0 er$0(
        .d(er$0$d),
        .q(er$0$q),
        .clock(er$0$clock)
    );
    vector$er$1 er$1(
        .d(er$1$d),
        .q(er$1$q),
        .clock(er$1$clock)
    );
    vector$er$2 er$2(
        .d(er$2$d),
        .q(er$2$q),
        .clock(er$2$clock)
    );
    vector$sdx$0 sdx$0(
        .d(sdx$0$d),
        .q(sdx$0$q),
        .clock(sdx$0$clock)
    );
    vector$sdx$1 sdx$1(
        .d(sdx$1$d),
        .q(sdx$1$q),
        .clock(sdx$1$clock)
    );
    vector$sdx$2 sdx$2(
        .d(sdx$2$d),
        .q(sdx$2$q),
        .clock(sdx$2$clock)
    );
    vector$sdy$0 sdy$0(
        .d(sdy$0$d),
        .q(sdy$0$q),
        .clock(sdy$0$clock)
    );
    vector$sdy$1 sdy$1(
        .d(sdy$1$d),
        .q(sdy$1$q),
        .clock(sdy$1$clock)
    );
    vector$sdy$2 sdy$2(
        .d(sdy$2$d),
        .q(sdy$2$q),
        .clock(sdy$2$clock)
    );
    vector$scls$0 scls$0(
        .dx(scls$0$dx),
        .dy(scls$0$dy),
        .left(scls$0$left),
        .right(scls$0$right),
        .flat(scls$0$flat),
        .owns(scls$0$owns),
        .g(scls$0$g),
        .h(scls$0$h)
    );
    vector$scls$1 scls$1(
        .dx(scls$1$dx),
        .dy(scls$1$dy),
        .left(scls$1$left),
        .right(scls$1$right),
        .flat(scls$1$flat),
        .owns(scls$1$owns),
        .g(scls$1$g),
        .h(scls$1$h)
    );
    vector$scls$2 scls$2(
        .dx(scls$2$dx),
        .dy(scls$2$dy),
        .left(scls$2$left),
        .right(scls$2$right),
        .flat(scls$2$flat),
        .owns(scls$2$owns),
        .g(scls$2$g),
        .h(scls$2$h)
    );
    vector$rej_ll$0 rej_ll$0(
        .e(rej_ll$0$e),
        .owns(rej_ll$0$owns),
        .rejects(rej_ll$0$rejects)
    );
    vector$rej_ll$1 rej_ll$1(
        .e(rej_ll$1$e),
        .owns(rej_ll$1$owns),
        .rejects(rej_ll$1$rejects)
    );
    vector$rej_ll$2 rej_ll$2(
        .e(rej_ll$2$e),
        .owns(rej_ll$2$owns),
        .rejects(rej_ll$2$rejects)
    );
    vector$rej_lm$0 rej_lm$0(
        .e(rej_lm$0$e),
        .owns(rej_lm$0$owns),
        .rejects(rej_lm$0$rejects)
    );
    vector$rej_lm$1 rej_lm$1(
        .e(rej_lm$1$e),
        .owns(rej_lm$1$owns),
        .rejects(rej_lm$1$rejects)
    );
    vector$rej_lm$2 rej_lm$2(
        .e(rej_lm$2$e),
        .owns(rej_lm$2$owns),
        .rejects(rej_lm$2$rejects)
    );
    vector$rej_lf$0 rej_lf$0(
        .e(rej_lf$0$e),
        .owns(rej_lf$0$owns),
        .rejects(rej_lf$0$rejects)
    );
    vector$rej_lf$1 rej_lf$1(
        .e(rej_lf$1$e),
        .owns(rej_lf$1$owns),
        .rejects(rej_lf$1$rejects)
    );
    vector$rej_lf$2 rej_lf$2(
        .e(rej_lf$2$e),
        .owns(rej_lf$2$owns),
        .rejects(rej_lf$2$rejects)
    );
    vector$rej_rf$0 rej_rf$0(
        .e(rej_rf$0$e),
        .owns(rej_rf$0$owns),
        .rejects(rej_rf$0$rejects)
    );
    vector$rej_rf$1 rej_rf$1(
        .e(rej_rf$1$e),
        .owns(rej_rf$1$owns),
        .rejects(rej_rf$1$rejects)
    );
    vector$rej_rf$2 rej_rf$2(
        .e(rej_rf$2$e),
        .owns(rej_rf$2$owns),
        .rejects(rej_rf$2$rejects)
    );
    vector$rej_rn$0 rej_rn$0(
        .e(rej_rn$0$e),
        .owns(rej_rn$0$owns),
        .rejects(rej_rn$0$rejects)
    );
    vector$rej_rn$1 rej_rn$1(
        .e(rej_rn$1$e),
        .owns(rej_rn$1$owns),
        .rejects(rej_rn$1$rejects)
    );
    vector$rej_rn$2 rej_rn$2(
        .e(rej_rn$2$e),
        .owns(rej_rn$2$owns),
        .rejects(rej_rn$2$rejects)
    );
    vector$tv tv(
        .d(tv$d),
        .q(tv$q),
        .clock(tv$clock)
    );
    vector$tx tx(
        .d(tx$d),
        .q(tx$q),
        .clock(tx$clock)
    );
    vector$te te(
        .d(te$d),
        .q(te$q),
        .clock(te$clock)
    );
    vector$ty ty(
        .d(ty$d),
        .q(ty$q),
        .clock(ty$clock)
    );
    vector$wx0 wx0(
        .d(wx0$d),
        .q(wx0$q),
        .clock(wx0$clock)
    );
    vector$wx1 wx1(
        .d(wx1$d),
        .q(wx1$q),
        .clock(wx1$clock)
    );
    vector$w$0 w$0(
        .d(w$0$d),
        .q(w$0$q),
        .clock(w$0$clock)
    );
    vector$w$1 w$1(
        .d(w$1$d),
        .q(w$1$q),
        .clock(w$1$clock)
    );
    vector$w$2 w$2(
        .d(w$2$d),
        .q(w$2$q),
        .clock(w$2$clock)
    );
    vector$wown$0 wown$0(
        .d(wown$0$d),
        .q(wown$0$q),
        .clock(wown$0$clock)
    );
    vector$wown$1 wown$1(
        .d(wown$1$d),
        .q(wown$1$q),
        .clock(wown$1$clock)
    );
    vector$wown$2 wown$2(
        .d(wown$2$d),
        .q(wown$2$q),
        .clock(wown$2$clock)
    );
    vector$wstep$0 wstep$0(
        .d(wstep$0$d),
        .q(wstep$0$q),
        .clock(wstep$0$clock)
    );
    vector$wstep$1 wstep$1(
        .d(wstep$1$d),
        .q(wstep$1$q),
        .clock(wstep$1$clock)
    );
    vector$wstep$2 wstep$2(
        .d(wstep$2$d),
        .q(wstep$2$q),
        .clock(wstep$2$clock)
    );
    vector$k_mant$0 k_mant$0(
        .d(k_mant$0$d),
        .q(k_mant$0$q),
        .clock(k_mant$0$clock)
    );
    vector$k_mant$1 k_mant$1(
        .d(k_mant$1$d),
        .q(k_mant$1$q),
        .clock(k_mant$1$clock)
    );
    vector$k_exp$0 k_exp$0(
        .d(k_exp$0$d),
        .q(k_exp$0$q),
        .clock(k_exp$0$clock)
    );
    vector$k_exp$1 k_exp$1(
        .d(k_exp$1$d),
        .q(k_exp$1$q),
        .clock(k_exp$1$clock)
    );
    vector$k_d1z$0 k_d1z$0(
        .d(k_d1z$0$d),
        .q(k_d1z$0$q),
        .clock(k_d1z$0$clock)
    );
    vector$k_d1z$1 k_d1z$1(
        .d(k_d1z$1$d),
        .q(k_d1z$1$q),
        .clock(k_d1z$1$clock)
    );
    vector$k_d2z$0 k_d2z$0(
        .d(k_d2z$0$d),
        .q(k_d2z$0$q),
        .clock(k_d2z$0$clock)
    );
    vector$k_d2z$1 k_d2z$1(
        .d(k_d2z$1$d),
        .q(k_d2z$1$q),
        .clock(k_d2z$1$clock)
    );
    vector$k_z0$0 k_z0$0(
        .d(k_z0$0$d),
        .q(k_z0$0$q),
        .clock(k_z0$0$clock)
    );
    vector$k_z0$1 k_z0$1(
        .d(k_z0$1$d),
        .q(k_z0$1$q),
        .clock(k_z0$1$clock)
    );
    vector$k_iw$0 k_iw$0(
        .d(k_iw$0$d),
        .q(k_iw$0$q),
        .clock(k_iw$0$clock)
    );
    vector$k_iw$1 k_iw$1(
        .d(k_iw$1$d),
        .q(k_iw$1$q),
        .clock(k_iw$1$clock)
    );
    vector$k_iw$2 k_iw$2(
        .d(k_iw$2$d),
        .q(k_iw$2$q),
        .clock(k_iw$2$clock)
    );
    vector$k_iw$3 k_iw$3(
        .d(k_iw$3$d),
        .q(k_iw$3$q),
        .clock(k_iw$3$clock)
    );
    vector$k_iw$4 k_iw$4(
        .d(k_iw$4$d),
        .q(k_iw$4$q),
        .clock(k_iw$4$clock)
    );
    vector$k_iw$5 k_iw$5(
        .d(k_iw$5$d),
        .q(k_iw$5$q),
        .clock(k_iw$5$clock)
    );
    vector$k_d1c$0 k_d1c$0(
        .d(k_d1c$0$d),
        .q(k_d1c$0$q),
        .clock(k_d1c$0$clock)
    );
    vector$k_d1c$1 k_d1c$1(
        .d(k_d1c$1$d),
        .q(k_d1c$1$q),
        .clock(k_d1c$1$clock)
    );
    vector$k_d1c$2 k_d1c$2(
        .d(k_d1c$2$d),
        .q(k_d1c$2$q),
        .clock(k_d1c$2$clock)
    );
    vector$k_d1c$3 k_d1c$3(
        .d(k_d1c$3$d),
        .q(k_d1c$3$q),
        .clock(k_d1c$3$clock)
    );
    vector$k_d1c$4 k_d1c$4(
        .d(k_d1c$4$d),
        .q(k_d1c$4$q),
        .clock(k_d1c$4$clock)
    );
    vector$k_d1c$5 k_d1c$5(
        .d(k_d1c$5$d),
        .q(k_d1c$5$q),
        .clock(k_d1c$5$clock)
    );
    vector$k_d2c$0 k_d2c$0(
        .d(k_d2c$0$d),
        .q(k_d2c$0$q),
        .clock(k_d2c$0$clock)
    );
    vector$k_d2c$1 k_d2c$1(
        .d(k_d2c$1$d),
        .q(k_d2c$1$q),
        .clock(k_d2c$1$clock)
    );
    vector$k_d2c$2 k_d2c$2(
        .d(k_d2c$2$d),
        .q(k_d2c$2$q),
        .clock(k_d2c$2$clock)
    );
    vector$k_d2c$3 k_d2c$3(
        .d(k_d2c$3$d),
        .q(k_d2c$3$q),
        .clock(k_d2c$3$clock)
    );
    vector$k_d2c$4 k_d2c$4(
        .d(k_d2c$4$d),
        .q(k_d2c$4$q),
        .clock(k_d2c$4$clock)
    );
    vector$k_d2c$5 k_d2c$5(
        .d(k_d2c$5$d),
        .q(k_d2c$5$q),
        .clock(k_d2c$5$clock)
    );
    vector$k_c0$0 k_c0$0(
        .d(k_c0$0$d),
        .q(k_c0$0$q),
        .clock(k_c0$0$clock)
    );
    vector$k_c0$1 k_c0$1(
        .d(k_c0$1$d),
        .q(k_c0$1$q),
        .clock(k_c0$1$clock)
    );
    vector$k_c0$2 k_c0$2(
        .d(k_c0$2$d),
        .q(k_c0$2$q),
        .clock(k_c0$2$clock)
    );
    vector$k_c0$3 k_c0$3(
        .d(k_c0$3$d),
        .q(k_c0$3$q),
        .clock(k_c0$3$clock)
    );
    vector$k_c0$4 k_c0$4(
        .d(k_c0$4$d),
        .q(k_c0$4$q),
        .clock(k_c0$4$clock)
    );
    vector$k_c0$5 k_c0$5(
        .d(k_c0$5$d),
        .q(k_c0$5$q),
        .clock(k_c0$5$clock)
    );
    vector$tag_dl tag_dl(
        .clock(tag_dl$clock),
        .en(tag_dl$en),
        .d(tag_dl$d),
        .q(tag_dl$q)
    );
    vector$o_x o_x(
        .d(o_x$d),
        .q(o_x$q),
        .clock(o_x$clock)
    );
    vector$o_y o_y(
        .d(o_y$d),
        .q(o_y$q),
        .clock(o_y$clock)
    );
    vector$place_z$0 place_z$0(
        .x(place_z$0$x),
        .y(place_z$0$y)
    );
    vector$place_rgb$0 place_rgb$0(
        .x(place_rgb$0$x),
        .y(place_rgb$0$y)
    );
    
    // Update code
    always @(*) begin
        sbusy$clock = clock;
        sc$clock = clock;
        dc$clock = clock;
        bx0$clock = clock;
        bx1$clock = clock;
        by0$clock = clock;
        by1$clock = clock;
        bneg$clock = clock;
        empty$clock = clock;
        cs$clock = clock;
        area$clock = clock;
        area_abs$clock = clock;
        exp_a$clock = clock;
        div_da$clock = clock;
        mant$clock = clock;
        sbusy$d = sbusy$q;
        sc$d = sc$q;
        dc$d = dc$q;
        bx0$d = bx0$q;
        bx1$d = bx1$q;
        by0$d = by0$q;
        by1$d = by1$q;
        bneg$d = bneg$q;
        empty$d = empty$q;
        cs$d = cs$q;
        area$d = area$q;
        area_abs$d = area_abs$q;
        exp_a$d = exp_a$q;
        div_da$d = div_da$q;
        mant$d = mant$q;
        sp$clock = clock;
        wp$clock = clock;
        ph$clock = clock;
        d1z$clock = clock;
        d2z$clock = clock;
        min_xr$clock = clock;
        max_xr$clock = clock;
        min_yr$clock = clock;
        max_yr$clock = clock;
        top_xr$clock = clock;
        sp$d = sp$q;
        wp$d = wp$q;
        ph$d = ph$q;
        d1z$d = d1z$q;
        d2z$d = d2z$q;
        min_xr$d = min_xr$q;
        max_xr$d = max_xr$q;
        min_yr$d = min_yr$q;
        max_yr$d = max_yr$q;
        top_xr$d = top_xr$q;
        sv$clock = clock;
        sy$clock = clock;
        sy1$clock = clock;
        sc0$clock = clock;
        sc1$clock = clock;
        sx0$clock = clock;
        sx1$clock = clock;
        sl$clock = clock;
        sr$clock = clock;
        tv$clock = clock;
        tx$clock = clock;
        te$clock = clock;
        ty$clock = clock;
        wx0$clock = clock;
        wx1$clock = clock;
        o_x$clock = clock;
        o_y$clock = clock;
        sv$d = sv$q;
        sy$d = sy$q;
        sy1$d = sy1$q;
        sc0$d = sc0$q;
        sc1$d = sc1$q;
        sx0$d = sx0$q;
        sx1$d = sx1$q;
        sl$d = sl$q;
        sr$d = sr$q;
        tv$d = tv$q;
        tx$d = tx$q;
        te$d = te$q;
        ty$d = ty$q;
        wx0$d = wx0$q;
        wx1$d = wx1$q;
        o_x$d = o_x$q;
        o_y$d = o_y$q;
        div_a$clock = clock;
        tag_dl$clock = clock;
        lanes$0$clock = clock;
        vx$0$clock = clock;
        vx$0$d = vx$0$q;
        vy$0$clock = clock;
        vy$0$d = vy$0$q;
        vz$0$clock = clock;
        vz$0$d = vz$0$q;
        viw$0$clock = clock;
        viw$0$d = viw$0$q;
        dx$0$clock = clock;
        dx$0$d = dx$0$q;
        dy$0$clock = clock;
        dy$0$d = dy$0$q;
        w0$0$clock = clock;
        w0$0$d = w0$0$q;
        d1c$0$clock = clock;
        d1c$0$d = d1c$0$q;
        d2c$0$clock = clock;
        d2c$0$d = d2c$0$q;
        el$0$clock = clock;
        el$0$d = el$0$q;
        er$0$clock = clock;
        er$0$d = er$0$q;
        sdx$0$clock = clock;
        sdx$0$d = sdx$0$q;
        sdy$0$clock = clock;
        sdy$0$d = sdy$0$q;
        w$0$clock = clock;
        w$0$d = w$0$q;
        wown$0$clock = clock;
        wown$0$d = wown$0$q;
        wstep$0$clock = clock;
        wstep$0$d = wstep$0$q;
        vx$1$clock = clock;
        vx$1$d = vx$1$q;
        vy$1$clock = clock;
        vy$1$d = vy$1$q;
        vz$1$clock = clock;
        vz$1$d = vz$1$q;
        viw$1$clock = clock;
        viw$1$d = viw$1$q;
        dx$1$clock = clock;
        dx$1$d = dx$1$q;
        dy$1$clock = clock;
        dy$1$d = dy$1$q;
        w0$1$clock = clock;
        w0$1$d = w0$1$q;
        d1c$1$clock = clock;
        d1c$1$d = d1c$1$q;
        d2c$1$clock = clock;
        d2c$1$d = d2c$1$q;
        el$1$clock = clock;
        el$1$d = el$1$q;
        er$1$clock = clock;
        er$1$d = er$1$q;
        sdx$1$clock = clock;
        sdx$1$d = sdx$1$q;
        sdy$1$clock = clock;
        sdy$1$d = sdy$1$q;
        w$1$clock = clock;
        w$1$d = w$1$q;
        wown$1$clock = clock;
        wown$1$d = wown$1$q;
        wstep$1$clock = clock;
        wstep$1$d = wstep$1$q;
        vx$2$clock = clock;
        vx$2$d = vx$2$q;
        vy$2$clock = clock;
        vy$2$d = vy$2$q;
        vz$2$clock = clock;
        vz$2$d = vz$2$q;
        viw$2$clock = clock;
        viw$2$d = viw$2$q;
        dx$2$clock = clock;
        dx$2$d = dx$2$q;
        dy$2$clock = clock;
        dy$2$d = dy$2$q;
        w0$2$clock = clock;
        w0$2$d = w0$2$q;
        d1c$2$clock = clock;
        d1c$2$d = d1c$2$q;
        d2c$2$clock = clock;
        d2c$2$d = d2c$2$q;
        el$2$clock = clock;
        el$2$d = el$2$q;
        er$2$clock = clock;
        er$2$d = er$2$q;
        sdx$2$clock = clock;
        sdx$2$d = sdx$2$q;
        sdy$2$clock = clock;
        sdy$2$d = sdy$2$q;
        w$2$clock = clock;
        w$2$d = w$2$q;
        wown$2$clock = clock;
        wown$2$d = wown$2$q;
        wstep$2$clock = clock;
        wstep$2$d = wstep$2$q;
        k_iw$0$clock = clock;
        k_iw$0$d = k_iw$0$q;
        k_d1c$0$clock = clock;
        k_d1c$0$d = k_d1c$0$q;
        k_d2c$0$clock = clock;
        k_d2c$0$d = k_d2c$0$q;
        k_c0$0$clock = clock;
        k_c0$0$d = k_c0$0$q;
        k_iw$1$clock = clock;
        k_iw$1$d = k_iw$1$q;
        k_d1c$1$clock = clock;
        k_d1c$1$d = k_d1c$1$q;
        k_d2c$1$clock = clock;
        k_d2c$1$d = k_d2c$1$q;
        k_c0$1$clock = clock;
        k_c0$1$d = k_c0$1$q;
        k_iw$2$clock = clock;
        k_iw$2$d = k_iw$2$q;
        k_d1c$2$clock = clock;
        k_d1c$2$d = k_d1c$2$q;
        k_d2c$2$clock = clock;
        k_d2c$2$d = k_d2c$2$q;
        k_c0$2$clock = clock;
        k_c0$2$d = k_c0$2$q;
        k_iw$3$clock = clock;
        k_iw$3$d = k_iw$3$q;
        k_d1c$3$clock = clock;
        k_d1c$3$d = k_d1c$3$q;
        k_d2c$3$clock = clock;
        k_d2c$3$d = k_d2c$3$q;
        k_c0$3$clock = clock;
        k_c0$3$d = k_c0$3$q;
        k_iw$4$clock = clock;
        k_iw$4$d = k_iw$4$q;
        k_d1c$4$clock = clock;
        k_d1c$4$d = k_d1c$4$q;
        k_d2c$4$clock = clock;
        k_d2c$4$d = k_d2c$4$q;
        k_c0$4$clock = clock;
        k_c0$4$d = k_c0$4$q;
        k_iw$5$clock = clock;
        k_iw$5$d = k_iw$5$q;
        k_d1c$5$clock = clock;
        k_d1c$5$d = k_d1c$5$q;
        k_d2c$5$clock = clock;
        k_d2c$5$d = k_d2c$5$q;
        k_c0$5$clock = clock;
        k_c0$5$d = k_c0$5$q;
        vc$0$clock = clock;
        vc$0$d = vc$0$q;
        vc$1$clock = clock;
        vc$1$d = vc$1$q;
        vc$2$clock = clock;
        vc$2$d = vc$2$q;
        vc$3$clock = clock;
        vc$3$d = vc$3$q;
        vc$4$clock = clock;
        vc$4$d = vc$4$q;
        vc$5$clock = clock;
        vc$5$d = vc$5$q;
        vc$6$clock = clock;
        vc$6$d = vc$6$q;
        vc$7$clock = clock;
        vc$7$d = vc$7$q;
        vc$8$clock = clock;
        vc$8$d = vc$8$q;
        mul_s$0$clock = clock;
        hold$0$clock = clock;
        hold$0$d = hold$0$q;
        k_mant$0$clock = clock;
        k_mant$0$d = k_mant$0$q;
        k_exp$0$clock = clock;
        k_exp$0$d = k_exp$0$q;
        k_d1z$0$clock = clock;
        k_d1z$0$d = k_d1z$0$q;
        k_d2z$0$clock = clock;
        k_d2z$0$d = k_d2z$0$q;
        k_z0$0$clock = clock;
        k_z0$0$d = k_z0$0$q;
        mul_s$1$clock = clock;
        hold$1$clock = clock;
        hold$1$d = hold$1$q;
        k_mant$1$clock = clock;
        k_mant$1$d = k_mant$1$q;
        k_exp$1$clock = clock;
        k_exp$1$d = k_exp$1$q;
        k_d1z$1$clock = clock;
        k_d1z$1$d = k_d1z$1$q;
        k_d2z$1$clock = clock;
        k_d2z$1$d = k_d2z$1$q;
        k_z0$1$clock = clock;
        k_z0$1$d = k_z0$1$q;
        g_mask$0 = 32'h0;
        g_z$0 = 32'h0;
        g_rgb$0 = 32'h0;
        g_mask$1 = g_mask$0;
        if (lanes$0$o_valid) begin
            g_mask$1 = g_mask$0 | at_mask$0;
        end
        place_z$0$x = lanes$0$o_z;
        place_rgb$0$x = lanes$0$o_rgb;
        g_z$1 = g_z$0 | place_z$0$y;
        g_rgb$1 = g_rgb$0 | place_rgb$0$y;
        out_mask = g_mask$1;
        out_z = g_z$1;
        out_rgb = g_rgb$1;
        out_valid = out_mask != 32'h0;
        run = ~(out_valid & ~out_ready);
        mul_s$0$en = run;
        mul_s$1$en = run;
        inp$ready = ~sbusy$q & run;
        take = inp$valid & inp$ready;
        idle = ~sbusy$q & ~sv$q & ~tv$q & (dc$q == 32'h0);
        set_ok = hold$1$q == 32'h0;
        if (sp$q) begin
            set_ok = hold$0$q == 32'h0;
        end
        hand = sbusy$q & (sc$q == at_walk) & (empty$q | (~sv$q & set_ok));
        div_a$hold = ~run;
        div_a$out_ready = 1'b1;
        div_a$inp_valid = 1'b1;
        div_a$inp_n = recip_n;
        div_a$inp_d = div_da$q;
        mant_c = mant$q;
        if (sc$q == at_mant) begin
            mant_c = div_a$out_q[(32'h0)+:(25)];
        end
        tag_dl$en = run;
        ex$0$x = vx$0$q;
        ey$0$x = vy$0$q;
        ez$0$x = vz$0$q;
        ux$0 = vx$0$q ^ half_xy;
        uy$0 = vy$0$q ^ half_xy;
        ex$1$x = vx$1$q;
        ey$1$x = vy$1$q;
        ez$1$x = vz$1$q;
        ux$1 = vx$1$q ^ half_xy;
        uy$1 = vy$1$q ^ half_xy;
        ex$2$x = vx$2$q;
        ey$2$x = vy$2$q;
        ez$2$x = vz$2$q;
        ux$2 = vx$2$q ^ half_xy;
        uy$2 = vy$2$q ^ half_xy;
        min_x = ux$0;
        max_x = ux$0;
        min_y = uy$0;
        max_y = uy$0;
        top_x = vx$0$q;
        if (ux$1 < min_x) begin
            min_x = ux$1;
        end
        if (ux$1 > max_x) begin
            max_x = ux$1;
        end
        if (uy$1 < min_y) begin
            min_y = uy$1;
            top_x = vx$1$q;
        end
        if (uy$1 > max_y) begin
            max_y = uy$1;
        end
        if (ux$2 < min_x) begin
            min_x = ux$2;
        end
        if (ux$2 > max_x) begin
            max_x = ux$2;
        end
        if (uy$2 < min_y) begin
            min_y = uy$2;
            top_x = vx$2$q;
        end
        if (uy$2 > max_y) begin
            max_y = uy$2;
        end
        ext_min_x$x = min_xr$q;
        ext_max_x$x = max_xr$q;
        ext_min_y$x = min_yr$q;
        ext_max_y$x = max_yr$q;
        lo_x = ext_min_x$y + px_half_m1;
        lo_y = ext_min_y$y + px_half_m1;
        hi_x = ext_max_x$y - px_half;
        hi_y = ext_max_y$y - px_half;
        neg_lo_x$x = lo_x;
        neg_lo_y$x = lo_y;
        neg_hi_x$x = hi_x;
        neg_hi_y$x = hi_y;
        hi_x_c = ((hi_x >> frac) & 13'h1fff);
        if (hi_x_c >= ((width) & 13'h1fff)) begin
            hi_x_c = ((width) & 13'h1fff) - 32'h1;
        end
        hi_y_c = ((hi_y >> frac) & 13'h1fff);
        if (hi_y_c >= ((height) & 13'h1fff)) begin
            hi_y_c = ((height) & 13'h1fff) - 32'h1;
        end
        ext_top$x = top_xr$q;
        neg_top$x = top_xr$q;
        top_c = ((ext_top$y >> frac) & 13'h1fff);
        if (top_c > bx1$q) begin
            top_c = bx1$q;
        end
        if (neg_top$neg | (top_c < bx0$q)) begin
            top_c = bx0$q;
        end
        cx0 = (((cs$q) & 17'h1ffff) << frac) + px_half;
        cy0 = (((by0$q) & 17'h1ffff) << frac) + px_half;
        area_neg$x = area$q;
        lead_a$x = area_abs$q;
        norm_a$x = area_abs$q;
        norm_a$exp = exp_a$q;
        mul_s$0$a = ex$1$y - ex$0$y;
        mul_s$0$b = ey$2$y - ey$0$y;
        mul_s$1$a = ey$1$y - ey$0$y;
        mul_s$1$b = ex$2$y - ex$0$y;
        if (sc$q == 32'h6) begin
            mul_s$0$a = dx$0$q;
            mul_s$0$b = cy0 - ey$1$y;
            mul_s$1$a = dy$0$q;
            mul_s$1$b = cx0 - ex$1$y;
        end
        if (sc$q == 32'h7) begin
            mul_s$0$a = dx$1$q;
            mul_s$0$b = cy0 - ey$2$y;
            mul_s$1$a = dy$1$q;
            mul_s$1$b = cx0 - ex$2$y;
        end
        if (sc$q == 32'h8) begin
            mul_s$0$a = dx$2$q;
            mul_s$0$b = cy0 - ey$0$y;
            mul_s$1$a = dy$2$q;
            mul_s$1$b = cx0 - ex$0$y;
        end
        out_l = 1'b0;
        out_lm = 1'b0;
        out_r = 1'b0;
        out_rn = 1'b0;
        dead = 1'b0;
        scls$0$dx = sdx$0$q;
        scls$0$dy = sdy$0$q;
        s_chunk$0 = scls$0$g << lg;
        s_less$0 = s_chunk$0 - scls$0$g;
        rej_ll$0$e = el$0$q - s_less$0;
        rej_lm$0$e = el$0$q + scls$0$g;
        rej_lf$0$e = el$0$q;
        rej_rf$0$e = er$0$q;
        rej_rn$0$e = er$0$q - s_chunk$0;
        rej_ll$0$owns = scls$0$owns;
        rej_lm$0$owns = scls$0$owns;
        rej_lf$0$owns = scls$0$owns;
        rej_rf$0$owns = scls$0$owns;
        rej_rn$0$owns = scls$0$owns;
        if (scls$0$left & rej_ll$0$rejects) begin
            out_l = 1'b1;
        end
        if (scls$0$left & rej_lm$0$rejects) begin
            out_lm = 1'b1;
        end
        if (scls$0$right & rej_rf$0$rejects) begin
            out_r = 1'b1;
        end
        if (scls$0$right & rej_rn$0$rejects) begin
            out_rn = 1'b1;
        end
        if (scls$0$flat & rej_lf$0$rejects) begin
            dead = 1'b1;
        end
        scls$1$dx = sdx$1$q;
        scls$1$dy = sdy$1$q;
        s_chunk$1 = scls$1$g << lg;
        s_less$1 = s_chunk$1 - scls$1$g;
        rej_ll$1$e = el$1$q - s_less$1;
        rej_lm$1$e = el$1$q + scls$1$g;
        rej_lf$1$e = el$1$q;
        rej_rf$1$e = er$1$q;
        rej_rn$1$e = er$1$q - s_chunk$1;
        rej_ll$1$owns = scls$1$owns;
        rej_lm$1$owns = scls$1$owns;
        rej_lf$1$owns = scls$1$owns;
        rej_rf$1$owns = scls$1$owns;
        rej_rn$1$owns = scls$1$owns;
        if (scls$1$left & rej_ll$1$rejects) begin
            out_l = 1'b1;
        end
        if (scls$1$left & rej_lm$1$rejects) begin
            out_lm = 1'b1;
        end
        if (scls$1$right & rej_rf$1$rejects) begin
            out_r = 1'b1;
        end
        if (scls$1$right & rej_rn$1$rejects) begin
            out_rn = 1'b1;
        end
        if (scls$1$flat & rej_lf$1$rejects) begin
            dead = 1'b1;
        end
        scls$2$dx = sdx$2$q;
        scls$2$dy = sdy$2$q;
        s_chunk$2 = scls$2$g << lg;
        s_less$2 = s_chunk$2 - scls$2$g;
        rej_ll$2$e = el$2$q - s_less$2;
        rej_lm$2$e = el$2$q + scls$2$g;
        rej_lf$2$e = el$2$q;
        rej_rf$2$e = er$2$q;
        rej_rn$2$e = er$2$q - s_chunk$2;
        rej_ll$2$owns = scls$2$owns;
        rej_lm$2$owns = scls$2$owns;
        rej_lf$2$owns = scls$2$owns;
        rej_rf$2$owns = scls$2$owns;
        rej_rn$2$owns = scls$2$owns;
        if (scls$2$left & rej_ll$2$rejects) begin
            out_l = 1'b1;
        end
        if (scls$2$left & rej_lm$2$rejects) begin
            out_lm = 1'b1;
        end
        if (scls$2$right & rej_rf$2$rejects) begin
            out_r = 1'b1;
        end
        if (scls$2$right & rej_rn$2$rejects) begin
            out_rn = 1'b1;
        end
        if (scls$2$flat & rej_lf$2$rejects) begin
            dead = 1'b1;
        end
        l_right = ~dead & out_l & (sl$q != sc1$q);
        l_left = ~dead & ~out_l & ~out_lm & (sl$q != sc0$q);
        r_left = ~dead & out_r & (sr$q != sc0$q);
        r_right = ~dead & ~out_r & ~out_rn & (sr$q != sc1$q);
        found = sv$q & ~l_right & ~l_left & ~r_left & ~r_right;
        row_empty = dead | out_l | out_r | (sl$q > sr$q);
        row_last = sy$q == sy1$q;
        walk_free = ~tv$q | (tx$q == te$q);
        c_mant = k_mant$0$q;
        if (wp$q) begin
            c_mant = k_mant$1$q;
        end
        c_exp = k_exp$0$q;
        if (ph$q[tap_exp]) begin
            c_exp = k_exp$1$q;
        end
        c_d1z = k_d1z$0$q;
        c_d2z = k_d2z$0$q;
        c_iw$0 = k_iw$0$q;
        c_iw$1 = k_iw$1$q;
        c_iw$2 = k_iw$2$q;
        if (ph$q[tap_z]) begin
            c_d1z = k_d1z$1$q;
            c_d2z = k_d2z$1$q;
            c_iw$0 = k_iw$3$q;
            c_iw$1 = k_iw$4$q;
            c_iw$2 = k_iw$5$q;
        end
        c_z0 = k_z0$0$q;
        if (ph$q[tap_z0]) begin
            c_z0 = k_z0$1$q;
        end
        c_d1c$0 = k_d1c$0$q;
        c_d2c$0 = k_d2c$0$q;
        if (ph$q[tap_c]) begin
            c_d1c$0 = k_d1c$3$q;
            c_d2c$0 = k_d2c$3$q;
        end
        c_c0$0 = k_c0$0$q;
        if (ph$q[tap_c0]) begin
            c_c0$0 = k_c0$3$q;
        end
        c_d1c$1 = k_d1c$1$q;
        c_d2c$1 = k_d2c$1$q;
        if (ph$q[tap_c]) begin
            c_d1c$1 = k_d1c$4$q;
            c_d2c$1 = k_d2c$4$q;
        end
        c_c0$1 = k_c0$1$q;
        if (ph$q[tap_c0]) begin
            c_c0$1 = k_c0$4$q;
        end
        c_d1c$2 = k_d1c$2$q;
        c_d2c$2 = k_d2c$2$q;
        if (ph$q[tap_c]) begin
            c_d1c$2 = k_d1c$5$q;
            c_d2c$2 = k_d2c$5$q;
        end
        c_c0$2 = k_c0$2$q;
        if (ph$q[tap_c0]) begin
            c_c0$2 = k_c0$5$q;
        end
        tag = (((ty$q) & 20'hfffff) << y_shift) | ((tx$q) & 20'hfffff);
        tag_dl$d = tag;
        lanes$0$run = run;
        lanes$0$load = found & ~row_empty & walk_free;
        lanes$0$valid = tv$q;
        lanes$0$x = tx$q;
        lanes$0$x0 = wx0$q;
        lanes$0$x1 = wx1$q;
        lanes$0$c_mant = c_mant;
        lanes$0$c_exp = c_exp;
        lanes$0$c_d1z = c_d1z;
        lanes$0$c_d2z = c_d2z;
        lanes$0$c_z0 = c_z0;
        lanes$0$g_0 = scls$0$g;
        lanes$0$w_0 = w$0$q;
        lanes$0$owns_0 = wown$0$q;
        lanes$0$c_iw_0 = c_iw$0;
        lanes$0$c_d1c_0 = c_d1c$0;
        lanes$0$c_d2c_0 = c_d2c$0;
        lanes$0$c_c0_0 = c_c0$0;
        lanes$0$g_1 = scls$1$g;
        lanes$0$w_1 = w$1$q;
        lanes$0$owns_1 = wown$1$q;
        lanes$0$c_iw_1 = c_iw$1;
        lanes$0$c_d1c_1 = c_d1c$1;
        lanes$0$c_d2c_1 = c_d2c$1;
        lanes$0$c_c0_1 = c_c0$1;
        lanes$0$g_2 = scls$2$g;
        lanes$0$w_2 = w$2$q;
        lanes$0$owns_2 = wown$2$q;
        lanes$0$c_iw_2 = c_iw$2;
        lanes$0$c_d1c_2 = c_d1c$2;
        lanes$0$c_d2c_2 = c_d2c$2;
        lanes$0$c_c0_2 = c_c0$2;
        out_x = o_x$q;
        out_y = o_y$q;
        if (run) begin
            if ((sc$q != 32'h0) & (sc$q != at_walk)) begin
                sc$d = sc$q + 32'h1;
            end
            if (dc$q != 32'h0) begin
                dc$d = dc$q - 32'h1;
            end
            if (hold$0$q != 32'h0) begin
                hold$0$d = hold$0$q - 32'h1;
            end
            if (hold$1$q != 32'h0) begin
                hold$1$d = hold$1$q - 32'h1;
            end
            ph$d = ph$q << one_s;
            if (wp$q) begin
                ph$d = (ph$q << one_s) | 64'h1;
            end
            if (take) begin
                sbusy$d = 1'b1;
                sc$d = 32'h1;
                vx$0$d = inp$v0_x;
                vx$1$d = inp$v1_x;
                vx$2$d = inp$v2_x;
                vy$0$d = inp$v0_y;
                vy$1$d = inp$v1_y;
                vy$2$d = inp$v2_y;
                vz$0$d = inp$v0_z;
                vz$1$d = inp$v1_z;
                vz$2$d = inp$v2_z;
                vc$0$d = inp$v0_c0;
                vc$1$d = inp$v0_c1;
                vc$2$d = inp$v0_c2;
                vc$3$d = inp$v1_c0;
                vc$4$d = inp$v1_c1;
                vc$5$d = inp$v1_c2;
                vc$6$d = inp$v2_c0;
                vc$7$d = inp$v2_c1;
                vc$8$d = inp$v2_c2;
                viw$0$d = inp$v0_iw;
                viw$1$d = inp$v1_iw;
                viw$2$d = inp$v2_iw;
            end
            if (sc$q == 32'h1) begin
                min_xr$d = min_x ^ half_xy;
                max_xr$d = max_x ^ half_xy;
                min_yr$d = min_y ^ half_xy;
                max_yr$d = max_y ^ half_xy;
                top_xr$d = top_x;
            end
            if (sc$q == 32'h2) begin
                bx0$d = ((lo_x >> frac) & 13'h1fff);
                if (neg_lo_x$neg) begin
                    bx0$d = 32'h0;
                end
                by0$d = ((lo_y >> frac) & 13'h1fff);
                if (neg_lo_y$neg) begin
                    by0$d = 32'h0;
                end
                bx1$d = hi_x_c;
                by1$d = hi_y_c;
                bneg$d = neg_hi_x$neg | neg_hi_y$neg;
            end
            if (sc$q == 32'h3) begin
                empty$d = bneg$q | (bx0$q > bx1$q) | (by0$q > by1$q);
                area$d = mul_s$0$p - mul_s$1$p;
                cs$d = top_c & chunk_p;
            end
            if (sc$q == 32'h4) begin
                area_abs$d = ((area$q) & 34'h3ffffffff);
                if (area_neg$neg) begin
                    area_abs$d = ((~area$q + 32'h1) & 34'h3ffffffff);
                    vx$1$d = vx$2$q;
                    vx$2$d = vx$1$q;
                    vy$1$d = vy$2$q;
                    vy$2$d = vy$1$q;
                    vz$1$d = vz$2$q;
                    vz$2$d = vz$1$q;
                    viw$1$d = viw$2$q;
                    viw$2$d = viw$1$q;
                    vc$3$d = vc$6$q;
                    vc$6$d = vc$3$q;
                    vc$4$d = vc$7$q;
                    vc$7$d = vc$4$q;
                    vc$5$d = vc$8$q;
                    vc$8$d = vc$5$q;
                end
            end
            if (sc$q == 32'h5) begin
                dx$0$d = ex$2$y - ex$1$y;
                dy$0$d = ey$2$y - ey$1$y;
                dx$1$d = ex$0$y - ex$2$y;
                dy$1$d = ey$0$y - ey$2$y;
                dx$2$d = ex$1$y - ex$0$y;
                dy$2$d = ey$1$y - ey$0$y;
                d1z$d = ez$1$y - ez$0$y;
                d2z$d = ez$2$y - ez$0$y;
                d1c$0$d = ((vc$3$q) & 9'h1ff) - ((vc$0$q) & 9'h1ff);
                d1c$1$d = ((vc$4$q) & 9'h1ff) - ((vc$1$q) & 9'h1ff);
                d1c$2$d = ((vc$5$q) & 9'h1ff) - ((vc$2$q) & 9'h1ff);
                d2c$0$d = ((vc$6$q) & 9'h1ff) - ((vc$0$q) & 9'h1ff);
                d2c$1$d = ((vc$7$q) & 9'h1ff) - ((vc$1$q) & 9'h1ff);
                d2c$2$d = ((vc$8$q) & 9'h1ff) - ((vc$2$q) & 9'h1ff);
                exp_a$d = lead_a$pos;
            end
            if (sc$q == 32'h6) begin
                div_da$d = norm_a$d;
            end
            if (sc$q == 32'h8) begin
                w0$0$d = mul_s$0$p - mul_s$1$p;
            end
            if (sc$q == 32'h9) begin
                w0$1$d = mul_s$0$p - mul_s$1$p;
            end
            if (sc$q == 32'ha) begin
                w0$2$d = mul_s$0$p - mul_s$1$p;
            end
            if (sc$q == at_mant) begin
                mant$d = mant_c;
            end
            if (tv$q) begin
                dc$d = drain;
                if (wp$q) begin
                    hold$1$d = held_m1;
                end
                else begin
                    hold$0$d = held_m1;
                end
                if (tx$q == te$q) begin
                    tv$d = 1'b0;
                end
                else begin
                    tx$d = tx$q + step;
                    w$0$d = w$0$q - wstep$0$q;
                    w$1$d = w$1$q - wstep$1$q;
                    w$2$d = w$2$q - wstep$2$q;
                end
            end
            if (sv$q) begin
                if (l_right) begin
                    sl$d = sl$q + step;
                    el$0$d = el$0$q - s_chunk$0;
                    el$1$d = el$1$q - s_chunk$1;
                    el$2$d = el$2$q - s_chunk$2;
                end
                if (l_left) begin
                    sl$d = sl$q - step;
                    el$0$d = el$0$q + s_chunk$0;
                    el$1$d = el$1$q + s_chunk$1;
                    el$2$d = el$2$q + s_chunk$2;
                end
                if (r_left) begin
                    sr$d = sr$q - step;
                    er$0$d = er$0$q + s_chunk$0;
                    er$1$d = er$1$q + s_chunk$1;
                    er$2$d = er$2$q + s_chunk$2;
                end
                if (r_right) begin
                    sr$d = sr$q + step;
                    er$0$d = er$0$q - s_chunk$0;
                    er$1$d = er$1$q - s_chunk$1;
                    er$2$d = er$2$q - s_chunk$2;
                end
                if (found & (row_empty | walk_free)) begin
                    if (row_last) begin
                        sv$d = 1'b0;
                    end
                    else begin
                        sy$d = sy$q + 32'h1;
                        el$0$d = el$0$q + scls$0$h;
                        er$0$d = er$0$q + scls$0$h;
                        el$1$d = el$1$q + scls$1$h;
                        er$1$d = er$1$q + scls$1$h;
                        el$2$d = el$2$q + scls$2$h;
                        er$2$d = er$2$q + scls$2$h;
                    end
                end
                if (found & ~row_empty & walk_free) begin
                    tv$d = 1'b1;
                    tx$d = sl$q;
                    te$d = sr$q;
                    ty$d = sy$q;
                    wx0$d = sx0$q;
                    wx1$d = sx1$q;
                    wp$d = sp$q;
                    w$0$d = el$0$q;
                    wown$0$d = scls$0$owns;
                    wstep$0$d = s_chunk$0;
                    w$1$d = el$1$q;
                    wown$1$d = scls$1$owns;
                    wstep$1$d = s_chunk$1;
                    w$2$d = el$2$q;
                    wown$2$d = scls$2$owns;
                    wstep$2$d = s_chunk$2;
                end
            end
            if (hand) begin
                sbusy$d = 1'b0;
                sc$d = 32'h0;
                if (~empty$q) begin
                    sv$d = 1'b1;
                    sp$d = ~sp$q;
                    sy$d = ((by0$q) & 10'h3ff);
                    sy1$d = ((by1$q) & 10'h3ff);
                    sx0$d = ((bx0$q) & 10'h3ff);
                    sx1$d = ((bx1$q) & 10'h3ff);
                    sc0$d = ((bx0$q) & 10'h3ff) & chunk;
                    sc1$d = ((bx1$q) & 10'h3ff) & chunk;
                    sl$d = ((cs$q) & 10'h3ff);
                    sr$d = ((cs$q) & 10'h3ff);
                    el$0$d = w0$0$q;
                    er$0$d = w0$0$q;
                    sdx$0$d = dx$0$q;
                    sdy$0$d = dy$0$q;
                    el$1$d = w0$1$q;
                    er$1$d = w0$1$q;
                    sdx$1$d = dx$1$q;
                    sdy$1$d = dy$1$q;
                    el$2$d = w0$2$q;
                    er$2$d = w0$2$q;
                    sdx$2$d = dx$2$q;
                    sdy$2$d = dy$2$q;
                    if (sp$q) begin
                        k_mant$0$d = mant_c;
                        k_exp$0$d = exp_a$q;
                        k_d1z$0$d = d1z$q;
                        k_d2z$0$d = d2z$q;
                        k_z0$0$d = vz$0$q;
                        k_iw$0$d = viw$0$q;
                        k_d1c$0$d = d1c$0$q;
                        k_d2c$0$d = d2c$0$q;
                        k_c0$0$d = vc$0$q;
                        k_iw$1$d = viw$1$q;
                        k_d1c$1$d = d1c$1$q;
                        k_d2c$1$d = d2c$1$q;
                        k_c0$1$d = vc$1$q;
                        k_iw$2$d = viw$2$q;
                        k_d1c$2$d = d1c$2$q;
                        k_d2c$2$d = d2c$2$q;
                        k_c0$2$d = vc$2$q;
                    end
                    else begin
                        k_mant$1$d = mant_c;
                        k_exp$1$d = exp_a$q;
                        k_d1z$1$d = d1z$q;
                        k_d2z$1$d = d2z$q;
                        k_z0$1$d = vz$0$q;
                        k_iw$3$d = viw$0$q;
                        k_d1c$3$d = d1c$0$q;
                        k_d2c$3$d = d2c$0$q;
                        k_c0$3$d = vc$0$q;
                        k_iw$4$d = viw$1$q;
                        k_d1c$4$d = d1c$1$q;
                        k_d2c$4$d = d2c$1$q;
                        k_c0$4$d = vc$1$q;
                        k_iw$5$d = viw$2$q;
                        k_d1c$5$d = d1c$2$q;
                        k_d2c$5$d = d2c$2$q;
                        k_c0$5$d = vc$2$q;
                    end
                end
            end
            o_x$d = ((tag_dl$q) & 10'h3ff);
            o_y$d = ((tag_dl$q >> y_shift) & 10'h3ff);
        end
    end
    
endmodule // vector


module vector$area(d,q,clock);
    
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
          
endmodule // vector$area


module vector$area_abs(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$area_abs


module vector$area_neg(x,neg);
    
    // Module arguments
    input wire  [34:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 35'h400000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // vector$area_neg


module vector$bneg(d,q,clock);
    
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
          
endmodule // vector$bneg


module vector$bx0(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$bx0


module vector$bx1(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$bx1


module vector$by0(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$by0


module vector$by1(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$by1


module vector$cs(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$cs


module vector$d1c$0(d,q,clock);
    
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
          
endmodule // vector$d1c$0


module vector$d1c$1(d,q,clock);
    
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
          
endmodule // vector$d1c$1


module vector$d1c$2(d,q,clock);
    
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
          
endmodule // vector$d1c$2


module vector$d1z(d,q,clock);
    
    // Module arguments
    input wire  [18:0] d;
    output reg  [18:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 19'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$d1z


module vector$d2c$0(d,q,clock);
    
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
          
endmodule // vector$d2c$0


module vector$d2c$1(d,q,clock);
    
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
          
endmodule // vector$d2c$1


module vector$d2c$2(d,q,clock);
    
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
          
endmodule // vector$d2c$2


module vector$d2z(d,q,clock);
    
    // Module arguments
    input wire  [18:0] d;
    output reg  [18:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 19'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$d2z


module vector$dc(d,q,clock);
    
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
          
endmodule // vector$dc


module vector$div_a(clock,inp_valid,inp_ready,hold,inp_n,inp_d,out_valid,out_ready,out_q,out_r);
    
    // Module arguments
    input wire  clock;
    input wire  inp_valid;
    output reg  inp_ready;
    input wire  hold;
    input wire  [57:0] inp_n;
    input wire  [33:0] inp_d;
    output reg  out_valid;
    input wire  out_ready;
    output reg  [25:0] out_q;
    output reg  [33:0] out_r;
    
    // Constant declarations
    localparam  n_msb = 8'h39;
    localparam  qm = 8'h19;
    localparam  q_sign = 26'h2000000;
    
    // Stub signals
    reg  stages$0$clock;
    reg  stages$0$enable;
    reg  stages$0$valid_in;
    reg  [33:0] stages$0$p_in;
    reg  [24:0] stages$0$x_in;
    reg  [33:0] stages$0$d_in;
    reg  stages$0$neg_in;
    wire  stages$0$valid;
    wire  [33:0] stages$0$p;
    wire  [24:0] stages$0$x;
    wire  [33:0] stages$0$d;
    wire  stages$0$neg;
    reg  stages$1$clock;
    reg  stages$1$enable;
    reg  stages$1$valid_in;
    reg  [33:0] stages$1$p_in;
    reg  [24:0] stages$1$x_in;
    reg  [33:0] stages$1$d_in;
    reg  stages$1$neg_in;
    wire  stages$1$valid;
    wire  [33:0] stages$1$p;
    wire  [24:0] stages$1$x;
    wire  [33:0] stages$1$d;
    wire  stages$1$neg;
    reg  stages$2$clock;
    reg  stages$2$enable;
    reg  stages$2$valid_in;
    reg  [33:0] stages$2$p_in;
    reg  [24:0] stages$2$x_in;
    reg  [33:0] stages$2$d_in;
    reg  stages$2$neg_in;
    wire  stages$2$valid;
    wire  [33:0] stages$2$p;
    wire  [24:0] stages$2$x;
    wire  [33:0] stages$2$d;
    wire  stages$2$neg;
    reg  stages$3$clock;
    reg  stages$3$enable;
    reg  stages$3$valid_in;
    reg  [33:0] stages$3$p_in;
    reg  [24:0] stages$3$x_in;
    reg  [33:0] stages$3$d_in;
    reg  stages$3$neg_in;
    wire  stages$3$valid;
    wire  [33:0] stages$3$p;
    wire  [24:0] stages$3$x;
    wire  [33:0] stages$3$d;
    wire  stages$3$neg;
    reg  stages$4$clock;
    reg  stages$4$enable;
    reg  stages$4$valid_in;
    reg  [33:0] stages$4$p_in;
    reg  [24:0] stages$4$x_in;
    reg  [33:0] stages$4$d_in;
    reg  stages$4$neg_in;
    wire  stages$4$valid;
    wire  [33:0] stages$4$p;
    wire  [24:0] stages$4$x;
    wire  [33:0] stages$4$d;
    wire  stages$4$neg;
    reg  stages$5$clock;
    reg  stages$5$enable;
    reg  stages$5$valid_in;
    reg  [33:0] stages$5$p_in;
    reg  [24:0] stages$5$x_in;
    reg  [33:0] stages$5$d_in;
    reg  stages$5$neg_in;
    wire  stages$5$valid;
    wire  [33:0] stages$5$p;
    wire  [24:0] stages$5$x;
    wire  [33:0] stages$5$d;
    wire  stages$5$neg;
    reg  stages$6$clock;
    reg  stages$6$enable;
    reg  stages$6$valid_in;
    reg  [33:0] stages$6$p_in;
    reg  [24:0] stages$6$x_in;
    reg  [33:0] stages$6$d_in;
    reg  stages$6$neg_in;
    wire  stages$6$valid;
    wire  [33:0] stages$6$p;
    wire  [24:0] stages$6$x;
    wire  [33:0] stages$6$d;
    wire  stages$6$neg;
    reg  stages$7$clock;
    reg  stages$7$enable;
    reg  stages$7$valid_in;
    reg  [33:0] stages$7$p_in;
    reg  [24:0] stages$7$x_in;
    reg  [33:0] stages$7$d_in;
    reg  stages$7$neg_in;
    wire  stages$7$valid;
    wire  [33:0] stages$7$p;
    wire  [24:0] stages$7$x;
    wire  [33:0] stages$7$d;
    wire  stages$7$neg;
    reg  stages$8$clock;
    reg  stages$8$enable;
    reg  stages$8$valid_in;
    reg  [33:0] stages$8$p_in;
    reg  [24:0] stages$8$x_in;
    reg  [33:0] stages$8$d_in;
    reg  stages$8$neg_in;
    wire  stages$8$valid;
    wire  [33:0] stages$8$p;
    wire  [24:0] stages$8$x;
    wire  [33:0] stages$8$d;
    wire  stages$8$neg;
    reg  stages$9$clock;
    reg  stages$9$enable;
    reg  stages$9$valid_in;
    reg  [33:0] stages$9$p_in;
    reg  [24:0] stages$9$x_in;
    reg  [33:0] stages$9$d_in;
    reg  stages$9$neg_in;
    wire  stages$9$valid;
    wire  [33:0] stages$9$p;
    wire  [24:0] stages$9$x;
    wire  [33:0] stages$9$d;
    wire  stages$9$neg;
    reg  stages$10$clock;
    reg  stages$10$enable;
    reg  stages$10$valid_in;
    reg  [33:0] stages$10$p_in;
    reg  [24:0] stages$10$x_in;
    reg  [33:0] stages$10$d_in;
    reg  stages$10$neg_in;
    wire  stages$10$valid;
    wire  [33:0] stages$10$p;
    wire  [24:0] stages$10$x;
    wire  [33:0] stages$10$d;
    wire  stages$10$neg;
    reg  stages$11$clock;
    reg  stages$11$enable;
    reg  stages$11$valid_in;
    reg  [33:0] stages$11$p_in;
    reg  [24:0] stages$11$x_in;
    reg  [33:0] stages$11$d_in;
    reg  stages$11$neg_in;
    wire  stages$11$valid;
    wire  [33:0] stages$11$p;
    wire  [24:0] stages$11$x;
    wire  [33:0] stages$11$d;
    wire  stages$11$neg;
    reg  stages$12$clock;
    reg  stages$12$enable;
    reg  stages$12$valid_in;
    reg  [33:0] stages$12$p_in;
    reg  [24:0] stages$12$x_in;
    reg  [33:0] stages$12$d_in;
    reg  stages$12$neg_in;
    wire  stages$12$valid;
    wire  [33:0] stages$12$p;
    wire  [24:0] stages$12$x;
    wire  [33:0] stages$12$d;
    wire  stages$12$neg;
    
    // Local signals
    reg  advance;
    reg  [57:0] m;
    reg  [24:0] last_x;
    
    // Sub module instances
    vector$div_a$stages$0 stages$0(
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
    vector$div_a$stages$1 stages$1(
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
    vector$div_a$stages$2 stages$2(
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
    vector$div_a$stages$3 stages$3(
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
    vector$div_a$stages$4 stages$4(
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
    vector$div_a$stages$5 stages$5(
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
    vector$div_a$stages$6 stages$6(
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
    vector$div_a$stages$7 stages$7(
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
    vector$div_a$stages$8 stages$8(
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
    vector$div_a$stages$9 stages$9(
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
    vector$div_a$stages$10 stages$10(
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
    vector$div_a$stages$11 stages$11(
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
    vector$div_a$stages$12 stages$12(
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
        out_q = ((last_x) & 26'h3ffffff);
        if (stages$12$neg) begin
            out_q = ((last_x) & 26'h3ffffff) | q_sign;
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
        stages$0$p_in = ((m >> qm) & 34'h3ffffffff);
        stages$0$x_in = m[(32'h0)+:(25)];
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
    
endmodule // vector$div_a


module vector$div_a$stages$0(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    vector$div_a$stages$0$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    vector$div_a$stages$0$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$div_a$stages$0$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    vector$div_a$stages$0$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    vector$div_a$stages$0$neg_r neg_r(
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
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
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
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
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
    
endmodule // vector$div_a$stages$0


module vector$div_a$stages$0$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$div_a$stages$0$d_r


module vector$div_a$stages$0$neg_r(d,q,clock);
    
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
          
endmodule // vector$div_a$stages$0$neg_r


module vector$div_a$stages$0$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$div_a$stages$0$p_r


module vector$div_a$stages$0$valid_r(d,q,clock);
    
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
          
endmodule // vector$div_a$stages$0$valid_r


module vector$div_a$stages$0$x_r(d,q,clock);
    
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
          
endmodule // vector$div_a$stages$0$x_r


module vector$div_a$stages$1(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [34:0] tp$2;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [24:0] tx$2;
    reg  [34:0] t$0;
    reg  [34:0] t$1;
    reg  [34:0] diff$0;
    reg  [34:0] diff$1;
    reg  [34:0] d1;
    
    // Sub module instances
    vector$div_a$stages$1$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    vector$div_a$stages$1$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$div_a$stages$1$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    vector$div_a$stages$1$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    vector$div_a$stages$1$neg_r neg_r(
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
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
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
            p_r$d = tp$2[(32'h0)+:(34)];
            x_r$d = tx$2;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$2[(32'h0)+:(34)] - 32'h1;
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
    
endmodule // vector$div_a$stages$1


module vector$div_a$stages$1$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$div_a$stages$1$d_r


module vector$div_a$stages$1$neg_r(d,q,clock);
    
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
          
endmodule // vector$div_a$stages$1$neg_r


module vector$div_a$stages$1$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$div_a$stages$1$p_r


module vector$div_a$stages$1$valid_r(d,q,clock);
    
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
          
endmodule // vector$div_a$stages$1$valid_r


module vector$div_a$stages$1$x_r(d,q,clock);
    
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
          
endmodule // vector$div_a$stages$1$x_r


module vector$div_a$stages$10(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [34:0] tp$2;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [24:0] tx$2;
    reg  [34:0] t$0;
    reg  [34:0] t$1;
    reg  [34:0] diff$0;
    reg  [34:0] diff$1;
    reg  [34:0] d1;
    
    // Sub module instances
    vector$div_a$stages$10$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    vector$div_a$stages$10$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$div_a$stages$10$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    vector$div_a$stages$10$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    vector$div_a$stages$10$neg_r neg_r(
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
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
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
            p_r$d = tp$2[(32'h0)+:(34)];
            x_r$d = tx$2;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$2[(32'h0)+:(34)] - 32'h1;
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
    
endmodule // vector$div_a$stages$10


module vector$div_a$stages$10$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$div_a$stages$10$d_r


module vector$div_a$stages$10$neg_r(d,q,clock);
    
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
          
endmodule // vector$div_a$stages$10$neg_r


module vector$div_a$stages$10$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$div_a$stages$10$p_r


module vector$div_a$stages$10$valid_r(d,q,clock);
    
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
          
endmodule // vector$div_a$stages$10$valid_r


module vector$div_a$stages$10$x_r(d,q,clock);
    
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
          
endmodule // vector$div_a$stages$10$x_r


module vector$div_a$stages$11(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [34:0] tp$2;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [24:0] tx$2;
    reg  [34:0] t$0;
    reg  [34:0] t$1;
    reg  [34:0] diff$0;
    reg  [34:0] diff$1;
    reg  [34:0] d1;
    
    // Sub module instances
    vector$div_a$stages$11$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    vector$div_a$stages$11$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$div_a$stages$11$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    vector$div_a$stages$11$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    vector$div_a$stages$11$neg_r neg_r(
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
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
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
            p_r$d = tp$2[(32'h0)+:(34)];
            x_r$d = tx$2;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$2[(32'h0)+:(34)] - 32'h1;
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
    
endmodule // vector$div_a$stages$11


module vector$div_a$stages$11$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$div_a$stages$11$d_r


module vector$div_a$stages$11$neg_r(d,q,clock);
    
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
          
endmodule // vector$div_a$stages$11$neg_r


module vector$div_a$stages$11$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$div_a$stages$11$p_r


module vector$div_a$stages$11$valid_r(d,q,clock);
    
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
          
endmodule // vector$div_a$stages$11$valid_r


module vector$div_a$stages$11$x_r(d,q,clock);
    
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
          
endmodule // vector$div_a$stages$11$x_r


module vector$div_a$stages$12(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b1;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [34:0] tp$2;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [24:0] tx$2;
    reg  [34:0] t$0;
    reg  [34:0] t$1;
    reg  [34:0] diff$0;
    reg  [34:0] diff$1;
    reg  [34:0] d1;
    
    // Sub module instances
    vector$div_a$stages$12$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    vector$div_a$stages$12$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$div_a$stages$12$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    vector$div_a$stages$12$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    vector$div_a$stages$12$neg_r neg_r(
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
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
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
            p_r$d = tp$2[(32'h0)+:(34)];
            x_r$d = tx$2;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$2[(32'h0)+:(34)] - 32'h1;
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
    
endmodule // vector$div_a$stages$12


module vector$div_a$stages$12$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$div_a$stages$12$d_r


module vector$div_a$stages$12$neg_r(d,q,clock);
    
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
          
endmodule // vector$div_a$stages$12$neg_r


module vector$div_a$stages$12$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$div_a$stages$12$p_r


module vector$div_a$stages$12$valid_r(d,q,clock);
    
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
          
endmodule // vector$div_a$stages$12$valid_r


module vector$div_a$stages$12$x_r(d,q,clock);
    
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
          
endmodule // vector$div_a$stages$12$x_r


module vector$div_a$stages$2(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [34:0] tp$2;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [24:0] tx$2;
    reg  [34:0] t$0;
    reg  [34:0] t$1;
    reg  [34:0] diff$0;
    reg  [34:0] diff$1;
    reg  [34:0] d1;
    
    // Sub module instances
    vector$div_a$stages$2$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    vector$div_a$stages$2$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$div_a$stages$2$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    vector$div_a$stages$2$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    vector$div_a$stages$2$neg_r neg_r(
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
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
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
            p_r$d = tp$2[(32'h0)+:(34)];
            x_r$d = tx$2;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$2[(32'h0)+:(34)] - 32'h1;
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
    
endmodule // vector$div_a$stages$2


module vector$div_a$stages$2$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$div_a$stages$2$d_r


module vector$div_a$stages$2$neg_r(d,q,clock);
    
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
          
endmodule // vector$div_a$stages$2$neg_r


module vector$div_a$stages$2$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$div_a$stages$2$p_r


module vector$div_a$stages$2$valid_r(d,q,clock);
    
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
          
endmodule // vector$div_a$stages$2$valid_r


module vector$div_a$stages$2$x_r(d,q,clock);
    
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
          
endmodule // vector$div_a$stages$2$x_r


module vector$div_a$stages$3(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [34:0] tp$2;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [24:0] tx$2;
    reg  [34:0] t$0;
    reg  [34:0] t$1;
    reg  [34:0] diff$0;
    reg  [34:0] diff$1;
    reg  [34:0] d1;
    
    // Sub module instances
    vector$div_a$stages$3$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    vector$div_a$stages$3$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$div_a$stages$3$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    vector$div_a$stages$3$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    vector$div_a$stages$3$neg_r neg_r(
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
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
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
            p_r$d = tp$2[(32'h0)+:(34)];
            x_r$d = tx$2;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$2[(32'h0)+:(34)] - 32'h1;
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
    
endmodule // vector$div_a$stages$3


module vector$div_a$stages$3$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$div_a$stages$3$d_r


module vector$div_a$stages$3$neg_r(d,q,clock);
    
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
          
endmodule // vector$div_a$stages$3$neg_r


module vector$div_a$stages$3$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$div_a$stages$3$p_r


module vector$div_a$stages$3$valid_r(d,q,clock);
    
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
          
endmodule // vector$div_a$stages$3$valid_r


module vector$div_a$stages$3$x_r(d,q,clock);
    
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
          
endmodule // vector$div_a$stages$3$x_r


module vector$div_a$stages$4(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [34:0] tp$2;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [24:0] tx$2;
    reg  [34:0] t$0;
    reg  [34:0] t$1;
    reg  [34:0] diff$0;
    reg  [34:0] diff$1;
    reg  [34:0] d1;
    
    // Sub module instances
    vector$div_a$stages$4$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    vector$div_a$stages$4$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$div_a$stages$4$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    vector$div_a$stages$4$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    vector$div_a$stages$4$neg_r neg_r(
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
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
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
            p_r$d = tp$2[(32'h0)+:(34)];
            x_r$d = tx$2;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$2[(32'h0)+:(34)] - 32'h1;
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
    
endmodule // vector$div_a$stages$4


module vector$div_a$stages$4$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$div_a$stages$4$d_r


module vector$div_a$stages$4$neg_r(d,q,clock);
    
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
          
endmodule // vector$div_a$stages$4$neg_r


module vector$div_a$stages$4$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$div_a$stages$4$p_r


module vector$div_a$stages$4$valid_r(d,q,clock);
    
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
          
endmodule // vector$div_a$stages$4$valid_r


module vector$div_a$stages$4$x_r(d,q,clock);
    
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
          
endmodule // vector$div_a$stages$4$x_r


module vector$div_a$stages$5(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [34:0] tp$2;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [24:0] tx$2;
    reg  [34:0] t$0;
    reg  [34:0] t$1;
    reg  [34:0] diff$0;
    reg  [34:0] diff$1;
    reg  [34:0] d1;
    
    // Sub module instances
    vector$div_a$stages$5$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    vector$div_a$stages$5$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$div_a$stages$5$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    vector$div_a$stages$5$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    vector$div_a$stages$5$neg_r neg_r(
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
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
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
            p_r$d = tp$2[(32'h0)+:(34)];
            x_r$d = tx$2;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$2[(32'h0)+:(34)] - 32'h1;
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
    
endmodule // vector$div_a$stages$5


module vector$div_a$stages$5$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$div_a$stages$5$d_r


module vector$div_a$stages$5$neg_r(d,q,clock);
    
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
          
endmodule // vector$div_a$stages$5$neg_r


module vector$div_a$stages$5$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$div_a$stages$5$p_r


module vector$div_a$stages$5$valid_r(d,q,clock);
    
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
          
endmodule // vector$div_a$stages$5$valid_r


module vector$div_a$stages$5$x_r(d,q,clock);
    
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
          
endmodule // vector$div_a$stages$5$x_r


module vector$div_a$stages$6(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [34:0] tp$2;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [24:0] tx$2;
    reg  [34:0] t$0;
    reg  [34:0] t$1;
    reg  [34:0] diff$0;
    reg  [34:0] diff$1;
    reg  [34:0] d1;
    
    // Sub module instances
    vector$div_a$stages$6$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    vector$div_a$stages$6$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$div_a$stages$6$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    vector$div_a$stages$6$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    vector$div_a$stages$6$neg_r neg_r(
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
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
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
            p_r$d = tp$2[(32'h0)+:(34)];
            x_r$d = tx$2;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$2[(32'h0)+:(34)] - 32'h1;
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
    
endmodule // vector$div_a$stages$6


module vector$div_a$stages$6$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$div_a$stages$6$d_r


module vector$div_a$stages$6$neg_r(d,q,clock);
    
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
          
endmodule // vector$div_a$stages$6$neg_r


module vector$div_a$stages$6$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$div_a$stages$6$p_r


module vector$div_a$stages$6$valid_r(d,q,clock);
    
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
          
endmodule // vector$div_a$stages$6$valid_r


module vector$div_a$stages$6$x_r(d,q,clock);
    
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
          
endmodule // vector$div_a$stages$6$x_r


module vector$div_a$stages$7(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [34:0] tp$2;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [24:0] tx$2;
    reg  [34:0] t$0;
    reg  [34:0] t$1;
    reg  [34:0] diff$0;
    reg  [34:0] diff$1;
    reg  [34:0] d1;
    
    // Sub module instances
    vector$div_a$stages$7$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    vector$div_a$stages$7$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$div_a$stages$7$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    vector$div_a$stages$7$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    vector$div_a$stages$7$neg_r neg_r(
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
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
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
            p_r$d = tp$2[(32'h0)+:(34)];
            x_r$d = tx$2;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$2[(32'h0)+:(34)] - 32'h1;
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
    
endmodule // vector$div_a$stages$7


module vector$div_a$stages$7$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$div_a$stages$7$d_r


module vector$div_a$stages$7$neg_r(d,q,clock);
    
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
          
endmodule // vector$div_a$stages$7$neg_r


module vector$div_a$stages$7$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$div_a$stages$7$p_r


module vector$div_a$stages$7$valid_r(d,q,clock);
    
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
          
endmodule // vector$div_a$stages$7$valid_r


module vector$div_a$stages$7$x_r(d,q,clock);
    
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
          
endmodule // vector$div_a$stages$7$x_r


module vector$div_a$stages$8(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [34:0] tp$2;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [24:0] tx$2;
    reg  [34:0] t$0;
    reg  [34:0] t$1;
    reg  [34:0] diff$0;
    reg  [34:0] diff$1;
    reg  [34:0] d1;
    
    // Sub module instances
    vector$div_a$stages$8$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    vector$div_a$stages$8$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$div_a$stages$8$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    vector$div_a$stages$8$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    vector$div_a$stages$8$neg_r neg_r(
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
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
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
            p_r$d = tp$2[(32'h0)+:(34)];
            x_r$d = tx$2;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$2[(32'h0)+:(34)] - 32'h1;
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
    
endmodule // vector$div_a$stages$8


module vector$div_a$stages$8$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$div_a$stages$8$d_r


module vector$div_a$stages$8$neg_r(d,q,clock);
    
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
          
endmodule // vector$div_a$stages$8$neg_r


module vector$div_a$stages$8$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$div_a$stages$8$p_r


module vector$div_a$stages$8$valid_r(d,q,clock);
    
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
          
endmodule // vector$div_a$stages$8$valid_r


module vector$div_a$stages$8$x_r(d,q,clock);
    
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
          
endmodule // vector$div_a$stages$8$x_r


module vector$div_a$stages$9(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [34:0] tp$2;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [24:0] tx$2;
    reg  [34:0] t$0;
    reg  [34:0] t$1;
    reg  [34:0] diff$0;
    reg  [34:0] diff$1;
    reg  [34:0] d1;
    
    // Sub module instances
    vector$div_a$stages$9$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    vector$div_a$stages$9$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$div_a$stages$9$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    vector$div_a$stages$9$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    vector$div_a$stages$9$neg_r neg_r(
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
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
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
            p_r$d = tp$2[(32'h0)+:(34)];
            x_r$d = tx$2;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$2[(32'h0)+:(34)] - 32'h1;
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
    
endmodule // vector$div_a$stages$9


module vector$div_a$stages$9$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$div_a$stages$9$d_r


module vector$div_a$stages$9$neg_r(d,q,clock);
    
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
          
endmodule // vector$div_a$stages$9$neg_r


module vector$div_a$stages$9$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$div_a$stages$9$p_r


module vector$div_a$stages$9$valid_r(d,q,clock);
    
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
          
endmodule // vector$div_a$stages$9$valid_r


module vector$div_a$stages$9$x_r(d,q,clock);
    
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
          
endmodule // vector$div_a$stages$9$x_r


module vector$div_da(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$div_da


module vector$dx$0(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$dx$0


module vector$dx$1(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$dx$1


module vector$dx$2(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$dx$2


module vector$dy$0(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$dy$0


module vector$dy$1(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$dy$1


module vector$dy$2(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$dy$2


module vector$el$0(d,q,clock);
    
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
          
endmodule // vector$el$0


module vector$el$1(d,q,clock);
    
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
          
endmodule // vector$el$1


module vector$el$2(d,q,clock);
    
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
          
endmodule // vector$el$2


module vector$empty(d,q,clock);
    
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
          
endmodule // vector$empty


module vector$er$0(d,q,clock);
    
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
          
endmodule // vector$er$0


module vector$er$1(d,q,clock);
    
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
          
endmodule // vector$er$1


module vector$er$2(d,q,clock);
    
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
          
endmodule // vector$er$2


module vector$ex$0(x,y);
    
    // Module arguments
    input wire  [15:0] x;
    output reg  [16:0] y;
    
    // Constant declarations
    localparam  msb = 8'hf;
    localparam  ext = 17'b10000000000000000;
    
    // Update code
    always @(*) begin
        y = ((x) & 17'h1ffff);
        if (x[msb]) begin
            y = ((x) & 17'h1ffff) | ext;
        end
    end
    
endmodule // vector$ex$0


module vector$ex$1(x,y);
    
    // Module arguments
    input wire  [15:0] x;
    output reg  [16:0] y;
    
    // Constant declarations
    localparam  msb = 8'hf;
    localparam  ext = 17'b10000000000000000;
    
    // Update code
    always @(*) begin
        y = ((x) & 17'h1ffff);
        if (x[msb]) begin
            y = ((x) & 17'h1ffff) | ext;
        end
    end
    
endmodule // vector$ex$1


module vector$ex$2(x,y);
    
    // Module arguments
    input wire  [15:0] x;
    output reg  [16:0] y;
    
    // Constant declarations
    localparam  msb = 8'hf;
    localparam  ext = 17'b10000000000000000;
    
    // Update code
    always @(*) begin
        y = ((x) & 17'h1ffff);
        if (x[msb]) begin
            y = ((x) & 17'h1ffff) | ext;
        end
    end
    
endmodule // vector$ex$2


module vector$exp_a(d,q,clock);
    
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
          
endmodule // vector$exp_a


module vector$ext_max_x(x,y);
    
    // Module arguments
    input wire  [15:0] x;
    output reg  [16:0] y;
    
    // Constant declarations
    localparam  msb = 8'hf;
    localparam  ext = 17'b10000000000000000;
    
    // Update code
    always @(*) begin
        y = ((x) & 17'h1ffff);
        if (x[msb]) begin
            y = ((x) & 17'h1ffff) | ext;
        end
    end
    
endmodule // vector$ext_max_x


module vector$ext_max_y(x,y);
    
    // Module arguments
    input wire  [15:0] x;
    output reg  [16:0] y;
    
    // Constant declarations
    localparam  msb = 8'hf;
    localparam  ext = 17'b10000000000000000;
    
    // Update code
    always @(*) begin
        y = ((x) & 17'h1ffff);
        if (x[msb]) begin
            y = ((x) & 17'h1ffff) | ext;
        end
    end
    
endmodule // vector$ext_max_y


module vector$ext_min_x(x,y);
    
    // Module arguments
    input wire  [15:0] x;
    output reg  [16:0] y;
    
    // Constant declarations
    localparam  msb = 8'hf;
    localparam  ext = 17'b10000000000000000;
    
    // Update code
    always @(*) begin
        y = ((x) & 17'h1ffff);
        if (x[msb]) begin
            y = ((x) & 17'h1ffff) | ext;
        end
    end
    
endmodule // vector$ext_min_x


module vector$ext_min_y(x,y);
    
    // Module arguments
    input wire  [15:0] x;
    output reg  [16:0] y;
    
    // Constant declarations
    localparam  msb = 8'hf;
    localparam  ext = 17'b10000000000000000;
    
    // Update code
    always @(*) begin
        y = ((x) & 17'h1ffff);
        if (x[msb]) begin
            y = ((x) & 17'h1ffff) | ext;
        end
    end
    
endmodule // vector$ext_min_y


module vector$ext_top(x,y);
    
    // Module arguments
    input wire  [15:0] x;
    output reg  [16:0] y;
    
    // Constant declarations
    localparam  msb = 8'hf;
    localparam  ext = 17'b10000000000000000;
    
    // Update code
    always @(*) begin
        y = ((x) & 17'h1ffff);
        if (x[msb]) begin
            y = ((x) & 17'h1ffff) | ext;
        end
    end
    
endmodule // vector$ext_top


module vector$ey$0(x,y);
    
    // Module arguments
    input wire  [15:0] x;
    output reg  [16:0] y;
    
    // Constant declarations
    localparam  msb = 8'hf;
    localparam  ext = 17'b10000000000000000;
    
    // Update code
    always @(*) begin
        y = ((x) & 17'h1ffff);
        if (x[msb]) begin
            y = ((x) & 17'h1ffff) | ext;
        end
    end
    
endmodule // vector$ey$0


module vector$ey$1(x,y);
    
    // Module arguments
    input wire  [15:0] x;
    output reg  [16:0] y;
    
    // Constant declarations
    localparam  msb = 8'hf;
    localparam  ext = 17'b10000000000000000;
    
    // Update code
    always @(*) begin
        y = ((x) & 17'h1ffff);
        if (x[msb]) begin
            y = ((x) & 17'h1ffff) | ext;
        end
    end
    
endmodule // vector$ey$1


module vector$ey$2(x,y);
    
    // Module arguments
    input wire  [15:0] x;
    output reg  [16:0] y;
    
    // Constant declarations
    localparam  msb = 8'hf;
    localparam  ext = 17'b10000000000000000;
    
    // Update code
    always @(*) begin
        y = ((x) & 17'h1ffff);
        if (x[msb]) begin
            y = ((x) & 17'h1ffff) | ext;
        end
    end
    
endmodule // vector$ey$2


module vector$ez$0(x,y);
    
    // Module arguments
    input wire  [17:0] x;
    output reg  [18:0] y;
    
    // Constant declarations
    localparam  msb = 8'h11;
    localparam  ext = 19'b1000000000000000000;
    
    // Update code
    always @(*) begin
        y = ((x) & 19'h7ffff);
        if (x[msb]) begin
            y = ((x) & 19'h7ffff) | ext;
        end
    end
    
endmodule // vector$ez$0


module vector$ez$1(x,y);
    
    // Module arguments
    input wire  [17:0] x;
    output reg  [18:0] y;
    
    // Constant declarations
    localparam  msb = 8'h11;
    localparam  ext = 19'b1000000000000000000;
    
    // Update code
    always @(*) begin
        y = ((x) & 19'h7ffff);
        if (x[msb]) begin
            y = ((x) & 19'h7ffff) | ext;
        end
    end
    
endmodule // vector$ez$1


module vector$ez$2(x,y);
    
    // Module arguments
    input wire  [17:0] x;
    output reg  [18:0] y;
    
    // Constant declarations
    localparam  msb = 8'h11;
    localparam  ext = 19'b1000000000000000000;
    
    // Update code
    always @(*) begin
        y = ((x) & 19'h7ffff);
        if (x[msb]) begin
            y = ((x) & 19'h7ffff) | ext;
        end
    end
    
endmodule // vector$ez$2


module vector$hold$0(d,q,clock);
    
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
          
endmodule // vector$hold$0


module vector$hold$1(d,q,clock);
    
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
          
endmodule // vector$hold$1


module vector$k_c0$0(d,q,clock);
    
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
          
endmodule // vector$k_c0$0


module vector$k_c0$1(d,q,clock);
    
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
          
endmodule // vector$k_c0$1


module vector$k_c0$2(d,q,clock);
    
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
          
endmodule // vector$k_c0$2


module vector$k_c0$3(d,q,clock);
    
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
          
endmodule // vector$k_c0$3


module vector$k_c0$4(d,q,clock);
    
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
          
endmodule // vector$k_c0$4


module vector$k_c0$5(d,q,clock);
    
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
          
endmodule // vector$k_c0$5


module vector$k_d1c$0(d,q,clock);
    
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
          
endmodule // vector$k_d1c$0


module vector$k_d1c$1(d,q,clock);
    
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
          
endmodule // vector$k_d1c$1


module vector$k_d1c$2(d,q,clock);
    
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
          
endmodule // vector$k_d1c$2


module vector$k_d1c$3(d,q,clock);
    
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
          
endmodule // vector$k_d1c$3


module vector$k_d1c$4(d,q,clock);
    
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
          
endmodule // vector$k_d1c$4


module vector$k_d1c$5(d,q,clock);
    
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
          
endmodule // vector$k_d1c$5


module vector$k_d1z$0(d,q,clock);
    
    // Module arguments
    input wire  [18:0] d;
    output reg  [18:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 19'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$k_d1z$0


module vector$k_d1z$1(d,q,clock);
    
    // Module arguments
    input wire  [18:0] d;
    output reg  [18:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 19'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$k_d1z$1


module vector$k_d2c$0(d,q,clock);
    
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
          
endmodule // vector$k_d2c$0


module vector$k_d2c$1(d,q,clock);
    
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
          
endmodule // vector$k_d2c$1


module vector$k_d2c$2(d,q,clock);
    
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
          
endmodule // vector$k_d2c$2


module vector$k_d2c$3(d,q,clock);
    
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
          
endmodule // vector$k_d2c$3


module vector$k_d2c$4(d,q,clock);
    
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
          
endmodule // vector$k_d2c$4


module vector$k_d2c$5(d,q,clock);
    
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
          
endmodule // vector$k_d2c$5


module vector$k_d2z$0(d,q,clock);
    
    // Module arguments
    input wire  [18:0] d;
    output reg  [18:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 19'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$k_d2z$0


module vector$k_d2z$1(d,q,clock);
    
    // Module arguments
    input wire  [18:0] d;
    output reg  [18:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 19'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$k_d2z$1


module vector$k_exp$0(d,q,clock);
    
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
          
endmodule // vector$k_exp$0


module vector$k_exp$1(d,q,clock);
    
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
          
endmodule // vector$k_exp$1


module vector$k_iw$0(d,q,clock);
    
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
          
endmodule // vector$k_iw$0


module vector$k_iw$1(d,q,clock);
    
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
          
endmodule // vector$k_iw$1


module vector$k_iw$2(d,q,clock);
    
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
          
endmodule // vector$k_iw$2


module vector$k_iw$3(d,q,clock);
    
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
          
endmodule // vector$k_iw$3


module vector$k_iw$4(d,q,clock);
    
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
          
endmodule // vector$k_iw$4


module vector$k_iw$5(d,q,clock);
    
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
          
endmodule // vector$k_iw$5


module vector$k_mant$0(d,q,clock);
    
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
          
endmodule // vector$k_mant$0


module vector$k_mant$1(d,q,clock);
    
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
          
endmodule // vector$k_mant$1


module vector$k_z0$0(d,q,clock);
    
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
          
endmodule // vector$k_z0$0


module vector$k_z0$1(d,q,clock);
    
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
          
endmodule // vector$k_z0$1


module vector$lanes$0(clock,run,load,g_0,g_1,g_2,valid,x,x0,x1,w_0,w_1,w_2,owns_0,owns_1,owns_2,c_mant,c_exp,c_d1z,c_d2z,c_z0,c_iw_0,c_iw_1,c_iw_2,c_d1c_0,c_d1c_1,c_d1c_2,c_d2c_0,c_d2c_1,c_d2c_2,c_c0_0,c_c0_1,c_c0_2,o_valid,o_z,o_rgb);
    
    // Module arguments
    input wire  clock;
    input wire  run;
    input wire  load;
    input wire  [34:0] g_0;
    input wire  [34:0] g_1;
    input wire  [34:0] g_2;
    input wire  valid;
    input wire  [9:0] x;
    input wire  [9:0] x0;
    input wire  [9:0] x1;
    input wire  [34:0] w_0;
    input wire  [34:0] w_1;
    input wire  [34:0] w_2;
    input wire  owns_0;
    input wire  owns_1;
    input wire  owns_2;
    input wire  [24:0] c_mant;
    input wire  [7:0] c_exp;
    input wire  [18:0] c_d1z;
    input wire  [18:0] c_d2z;
    input wire  [17:0] c_z0;
    input wire  [15:0] c_iw_0;
    input wire  [15:0] c_iw_1;
    input wire  [15:0] c_iw_2;
    input wire  [8:0] c_d1c_0;
    input wire  [8:0] c_d1c_1;
    input wire  [8:0] c_d1c_2;
    input wire  [8:0] c_d2c_0;
    input wire  [8:0] c_d2c_1;
    input wire  [8:0] c_d2c_2;
    input wire  [7:0] c_c0_0;
    input wire  [7:0] c_c0_1;
    input wire  [7:0] c_c0_2;
    output reg  o_valid;
    output reg  [15:0] o_z;
    output reg  [23:0] o_rgb;
    
    // Constant declarations
    localparam  idx = 10'b0;
    localparam  m1 = 35'h0;
    localparam  m2 = 35'h0;
    localparam  m4 = 35'h0;
    localparam  one_s = 8'h1;
    localparam  ch1 = 8'h8;
    localparam  ch2 = 8'h10;
    localparam  two_s = 8'h2;
    localparam  recip_n = 58'h100000000000000;
    localparam  one = 28'h4000000;
    localparam  half_pair = 8'h1c;
    localparam  full = 8'hff;
    
    // Stub signals
    wire  persp$on;
    reg  [34:0] off$0$d;
    wire  [34:0] off$0$q;
    reg  off$0$clock;
    reg  [34:0] off$1$d;
    wire  [34:0] off$1$q;
    reg  off$1$clock;
    reg  [34:0] off$2$d;
    wire  [34:0] off$2$q;
    reg  off$2$clock;
    reg  [34:0] rej$0$e;
    reg  rej$0$owns;
    wire  rej$0$rejects;
    reg  [34:0] rej$1$e;
    reg  rej$1$owns;
    wire  rej$1$rejects;
    reg  [34:0] rej$2$e;
    reg  rej$2$owns;
    wire  rej$2$rejects;
    reg  hit_dl$clock;
    reg  hit_dl$en;
    reg  hit_dl$d;
    wire  hit_dl$q;
    reg  div$clock;
    reg  div$inp_valid;
    wire  div$inp_ready;
    reg  div$hold;
    reg  [57:0] div$inp_n;
    reg  [33:0] div$inp_d;
    wire  div$out_valid;
    reg  div$out_ready;
    wire  [25:0] div$out_q;
    wire  [33:0] div$out_r;
    reg  mul_a$clock;
    reg  mul_a$en;
    reg  [34:0] mul_a$a;
    reg  [25:0] mul_a$b;
    wire  [60:0] mul_a$p;
    reg  mul_b$clock;
    reg  mul_b$en;
    reg  [34:0] mul_b$a;
    reg  [25:0] mul_b$b;
    wire  [60:0] mul_b$p;
    reg  mul_z1$clock;
    reg  mul_z1$en;
    reg  [18:0] mul_z1$a;
    reg  [27:0] mul_z1$b;
    wire  [47:0] mul_z1$p;
    reg  mul_z2$clock;
    reg  mul_z2$en;
    reg  [18:0] mul_z2$a;
    reg  [27:0] mul_z2$b;
    wire  [47:0] mul_z2$p;
    reg  mul_l$0$clock;
    reg  mul_l$0$en;
    reg  [27:0] mul_l$0$a;
    reg  [16:0] mul_l$0$b;
    wire  [44:0] mul_l$0$p;
    reg  mul_l$1$clock;
    reg  mul_l$1$en;
    reg  [27:0] mul_l$1$a;
    reg  [16:0] mul_l$1$b;
    wire  [44:0] mul_l$1$p;
    reg  mul_l$2$clock;
    reg  mul_l$2$en;
    reg  [27:0] mul_l$2$a;
    reg  [16:0] mul_l$2$b;
    wire  [44:0] mul_l$2$p;
    reg  mul_ra$clock;
    reg  mul_ra$en;
    reg  [27:0] mul_ra$a;
    reg  [25:0] mul_ra$b;
    wire  [53:0] mul_ra$p;
    reg  mul_rb$clock;
    reg  mul_rb$en;
    reg  [27:0] mul_rb$a;
    reg  [25:0] mul_rb$b;
    wire  [53:0] mul_rb$p;
    reg  mul_c1$0$clock;
    reg  mul_c1$0$en;
    reg  [8:0] mul_c1$0$a;
    reg  [27:0] mul_c1$0$b;
    wire  [37:0] mul_c1$0$p;
    reg  mul_c1$1$clock;
    reg  mul_c1$1$en;
    reg  [8:0] mul_c1$1$a;
    reg  [27:0] mul_c1$1$b;
    wire  [37:0] mul_c1$1$p;
    reg  mul_c1$2$clock;
    reg  mul_c1$2$en;
    reg  [8:0] mul_c1$2$a;
    reg  [27:0] mul_c1$2$b;
    wire  [37:0] mul_c1$2$p;
    reg  mul_c2$0$clock;
    reg  mul_c2$0$en;
    reg  [8:0] mul_c2$0$a;
    reg  [27:0] mul_c2$0$b;
    wire  [37:0] mul_c2$0$p;
    reg  mul_c2$1$clock;
    reg  mul_c2$1$en;
    reg  [8:0] mul_c2$1$a;
    reg  [27:0] mul_c2$1$b;
    wire  [37:0] mul_c2$1$p;
    reg  mul_c2$2$clock;
    reg  mul_c2$2$en;
    reg  [8:0] mul_c2$2$a;
    reg  [27:0] mul_c2$2$b;
    wire  [37:0] mul_c2$2$p;
    reg  [29:0] norm_s$x;
    reg  [7:0] norm_s$exp;
    wire  [33:0] norm_s$d;
    reg  [33:0] div_d$d;
    wire  [33:0] div_d$q;
    reg  div_d$clock;
    reg  [60:0] rs_a$x;
    reg  [7:0] rs_a$by;
    wire  [27:0] rs_a$y;
    reg  [60:0] rs_b$x;
    reg  [7:0] rs_b$by;
    wire  [27:0] rs_b$y;
    reg  [27:0] a3$d;
    wire  [27:0] a3$q;
    reg  a3$clock;
    reg  [27:0] b3$d;
    wire  [27:0] b3$q;
    reg  b3$clock;
    reg  [47:0] rs_z$x;
    reg  [7:0] rs_z$by;
    wire  [35:0] rs_z$y;
    reg  [18:0] rs_z0$x;
    reg  [7:0] rs_z0$by;
    wire  [35:0] rs_z0$y;
    reg  [17:0] ez0$x;
    wire  [18:0] ez0$y;
    reg  [35:0] z6$d;
    wire  [35:0] z6$q;
    reg  z6$clock;
    reg  [35:0] depth_of$x;
    wire  depth_of$neg;
    wire  depth_of$over;
    wire  [15:0] depth_of$low;
    reg  dtag_dl$clock;
    reg  dtag_dl$en;
    reg  [16:0] dtag_dl$d;
    wire  [16:0] dtag_dl$q;
    reg  [44:0] rs_q$0$x;
    reg  [7:0] rs_q$0$by;
    wire  [27:0] rs_q$0$y;
    reg  [44:0] rs_q$1$x;
    reg  [7:0] rs_q$1$by;
    wire  [27:0] rs_q$1$y;
    reg  [44:0] rs_q$2$x;
    reg  [7:0] rs_q$2$by;
    wire  [27:0] rs_q$2$y;
    reg  [27:0] q6$0$d;
    wire  [27:0] q6$0$q;
    reg  q6$0$clock;
    reg  [27:0] q6$1$d;
    wire  [27:0] q6$1$q;
    reg  q6$1$clock;
    reg  [27:0] q6$2$d;
    wire  [27:0] q6$2$q;
    reg  q6$2$clock;
    reg  [27:0] eq$0$x;
    wire  [29:0] eq$0$y;
    reg  [27:0] eq$1$x;
    wire  [29:0] eq$1$y;
    reg  [27:0] eq$2$x;
    wire  [29:0] eq$2$y;
    reg  [29:0] sum7$d;
    wire  [29:0] sum7$q;
    reg  sum7$clock;
    reg  [29:0] lead_s$x;
    wire  [7:0] lead_s$pos;
    reg  [29:0] sum8$d;
    wire  [29:0] sum8$q;
    reg  sum8$clock;
    reg  [7:0] exp8$d;
    wire  [7:0] exp8$q;
    reg  exp8$clock;
    reg  q_dl$clock;
    reg  q_dl$en;
    reg  [55:0] q_dl$d;
    wire  [55:0] q_dl$q;
    reg  exp_dl$clock;
    reg  exp_dl$en;
    reg  [7:0] exp_dl$d;
    wire  [7:0] exp_dl$q;
    reg  ab_dl$clock;
    reg  ab_dl$en;
    reg  [55:0] ab_dl$d;
    wire  [55:0] ab_dl$q;
    reg  [53:0] rs_ra$x;
    reg  [7:0] rs_ra$by;
    wire  [27:0] rs_ra$y;
    reg  [53:0] rs_rb$x;
    reg  [7:0] rs_rb$by;
    wire  [27:0] rs_rb$y;
    reg  [27:0] ca11$d;
    wire  [27:0] ca11$q;
    reg  ca11$clock;
    reg  [27:0] cb11$d;
    wire  [27:0] cb11$q;
    reg  cb11$clock;
    reg  [37:0] rs_c$0$x;
    reg  [7:0] rs_c$0$by;
    wire  [31:0] rs_c$0$y;
    reg  [37:0] rs_c$1$x;
    reg  [7:0] rs_c$1$by;
    wire  [31:0] rs_c$1$y;
    reg  [37:0] rs_c$2$x;
    reg  [7:0] rs_c$2$by;
    wire  [31:0] rs_c$2$y;
    reg  [8:0] rs_c0$0$x;
    reg  [7:0] rs_c0$0$by;
    wire  [31:0] rs_c0$0$y;
    reg  [8:0] rs_c0$1$x;
    reg  [7:0] rs_c0$1$by;
    wire  [31:0] rs_c0$1$y;
    reg  [8:0] rs_c0$2$x;
    reg  [7:0] rs_c0$2$by;
    wire  [31:0] rs_c0$2$y;
    reg  [31:0] c14$0$d;
    wire  [31:0] c14$0$q;
    reg  c14$0$clock;
    reg  [31:0] c14$1$d;
    wire  [31:0] c14$1$q;
    reg  c14$1$clock;
    reg  [31:0] c14$2$d;
    wire  [31:0] c14$2$q;
    reg  c14$2$clock;
    reg  [31:0] color_of$0$x;
    wire  color_of$0$neg;
    wire  color_of$0$over;
    wire  [7:0] color_of$0$low;
    reg  [31:0] color_of$1$x;
    wire  color_of$1$neg;
    wire  color_of$1$over;
    wire  [7:0] color_of$1$low;
    reg  [31:0] color_of$2$x;
    wire  color_of$2$neg;
    wire  color_of$2$over;
    wire  [7:0] color_of$2$low;
    reg  ov$d;
    wire  ov$q;
    reg  ov$clock;
    reg  [15:0] oz$d;
    wire  [15:0] oz$q;
    reg  oz$clock;
    reg  [7:0] orgb$0$d;
    wire  [7:0] orgb$0$q;
    reg  orgb$0$clock;
    reg  [7:0] orgb$1$d;
    wire  [7:0] orgb$1$q;
    reg  orgb$1$clock;
    reg  [7:0] orgb$2$d;
    wire  [7:0] orgb$2$q;
    reg  orgb$2$clock;
    
    // Local signals
    reg  [34:0] g$0;
    reg  [34:0] g$1;
    reg  [34:0] g$2;
    reg  [34:0] w$0;
    reg  [34:0] w$1;
    reg  [34:0] w$2;
    reg  owns$0;
    reg  owns$1;
    reg  owns$2;
    reg  [15:0] c_iw$0;
    reg  [15:0] c_iw$1;
    reg  [15:0] c_iw$2;
    reg  [8:0] c_d1c$0;
    reg  [8:0] c_d1c$1;
    reg  [8:0] c_d1c$2;
    reg  [8:0] c_d2c$0;
    reg  [8:0] c_d2c$1;
    reg  [8:0] c_d2c$2;
    reg  [7:0] c_c0$0;
    reg  [7:0] c_c0$1;
    reg  [7:0] c_c0$2;
    reg  [34:0] e$0;
    reg  [34:0] e$1;
    reg  [34:0] e$2;
    reg  [9:0] px;
    reg  covered;
    reg  hit;
    reg  [16:0] dtag;
    reg  [29:0] sum_c;
    reg  [55:0] q_pair;
    reg  [55:0] ab_pair;
    reg  [27:0] ca;
    reg  [27:0] cb;
    
    // Sub module instances
    vector$lanes$0$persp persp(
        .on(persp$on)
    );
    vector$lanes$0$off$0 off$0(
        .d(off$0$d),
        .q(off$0$q),
        .clock(off$0$clock)
    );
    vector$lanes$0$off$1 off$1(
        .d(off$1$d),
        .q(off$1$q),
        .clock(off$1$clock)
    );
    vector$lanes$0$off$2 off$2(
        .d(off$2$d),
        .q(off$2$q),
        .clock(off$2$clock)
    );
    vector$lanes$0$rej$0 rej$0(
        .e(rej$0$e),
        .owns(rej$0$owns),
        .rejects(rej$0$rejects)
    );
    vector$lanes$0$rej$1 rej$1(
        .e(rej$1$e),
        .owns(rej$1$owns),
        .rejects(rej$1$rejects)
    );
    vector$lanes$0$rej$2 rej$2(
        .e(rej$2$e),
        .owns(rej$2$owns),
        .rejects(rej$2$rejects)
    );
    vector$lanes$0$hit_dl hit_dl(
        .clock(hit_dl$clock),
        .en(hit_dl$en),
        .d(hit_dl$d),
        .q(hit_dl$q)
    );
    vector$lanes$0$div div(
        .clock(div$clock),
        .inp_valid(div$inp_valid),
        .inp_ready(div$inp_ready),
        .hold(div$hold),
        .inp_n(div$inp_n),
        .inp_d(div$inp_d),
        .out_valid(div$out_valid),
        .out_ready(div$out_ready),
        .out_q(div$out_q),
        .out_r(div$out_r)
    );
    vector$lanes$0$mul_a mul_a(
        .clock(mul_a$clock),
        .en(mul_a$en),
        .a(mul_a$a),
        .b(mul_a$b),
        .p(mul_a$p)
    );
    vector$lanes$0$mul_b mul_b(
        .clock(mul_b$clock),
        .en(mul_b$en),
        .a(mul_b$a),
        .b(mul_b$b),
        .p(mul_b$p)
    );
    vector$lanes$0$mul_z1 mul_z1(
        .clock(mul_z1$clock),
        .en(mul_z1$en),
        .a(mul_z1$a),
        .b(mul_z1$b),
        .p(mul_z1$p)
    );
    vector$lanes$0$mul_z2 mul_z2(
        .clock(mul_z2$clock),
        .en(mul_z2$en),
        .a(mul_z2$a),
        .b(mul_z2$b),
        .p(mul_z2$p)
    );
    vector$lanes$0$mul_l$0 mul_l$0(
        .clock(mul_l$0$clock),
        .en(mul_l$0$en),
        .a(mul_l$0$a),
        .b(mul_l$0$b),
        .p(mul_l$0$p)
    );
    vector$lanes$0$mul_l$1 mul_l$1(
        .clock(mul_l$1$clock),
        .en(mul_l$1$en),
        .a(mul_l$1$a),
        .b(mul_l$1$b),
        .p(mul_l$1$p)
    );
    vector$lanes$0$mul_l$2 mul_l$2(
        .clock(mul_l$2$clock),
        .en(mul_l$2$en),
        .a(mul_l$2$a),
        .b(mul_l$2$b),
        .p(mul_l$2$p)
    );
    vector$lanes$0$mul_ra mul_ra(
        .clock(mul_ra$clock),
        .en(mul_ra$en),
        .a(mul_ra$a),
        .b(mul_ra$b),
        .p(mul_ra$p)
    );
    vector$lanes$0$mul_rb mul_rb(
        .clock(mul_rb$clock),
        .en(mul_rb$en),
        .a(mul_rb$a),
        .b(mul_rb$b),
        .p(mul_rb$p)
    );
    vector$lanes$0$mul_c1$0 mul_c1$0(
        .clock(mul_c1$0$clock),
        .en(mul_c1$0$en),
        .a(mul_c1$0$a),
        .b(mul_c1$0$b),
        .p(mul_c1$0$p)
    );
    vector$lanes$0$mul_c1$1 mul_c1$1(
        .clock(mul_c1$1$clock),
        .en(mul_c1$1$en),
        .a(mul_c1$1$a),
        .b(mul_c1$1$b),
        .p(mul_c1$1$p)
    );
    vector$lanes$0$mul_c1$2 mul_c1$2(
        .clock(mul_c1$2$clock),
        .en(mul_c1$2$en),
        .a(mul_c1$2$a),
        .b(mul_c1$2$b),
        .p(mul_c1$2$p)
    );
    vector$lanes$0$mul_c2$0 mul_c2$0(
        .clock(mul_c2$0$clock),
        .en(mul_c2$0$en),
        .a(mul_c2$0$a),
        .b(mul_c2$0$b),
        .p(mul_c2$0$p)
    );
    vector$lanes$0$mul_c2$1 mul_c2$1(
        .clock(mul_c2$1$clock),
        .en(mul_c2$1$en),
        .a(mul_c2$1$a),
        .b(mul_c2$1$b),
        .p(mul_c2$1$p)
    );
    vector$lanes$0$mul_c2$2 mul_c2$2(
        .clock(mul_c2$2$clock),
        .en(mul_c2$2$en),
        .a(mul_c2$2$a),
        .b(mul_c2$2$b),
        .p(mul_c2$2$p)
    );
    vector$lanes$0$norm_s norm_s(
        .x(norm_s$x),
        .exp(norm_s$exp),
        .d(norm_s$d)
    );
    vector$lanes$0$div_d div_d(
        .d(div_d$d),
        .q(div_d$q),
        .clock(div_d$clock)
    );
    vector$lanes$0$rs_a rs_a(
        .x(rs_a$x),
        .by(rs_a$by),
        .y(rs_a$y)
    );
    vector$lanes$0$rs_b rs_b(
        .x(rs_b$x),
        .by(rs_b$by),
        .y(rs_b$y)
    );
    vector$lanes$0$a3 a3(
        .d(a3$d),
        .q(a3$q),
        .clock(a3$clock)
    );
    vector$lanes$0$b3 b3(
        .d(b3$d),
        .q(b3$q),
        .clock(b3$clock)
    );
    vector$lanes$0$rs_z rs_z(
        .x(rs_z$x),
        .by(rs_z$by),
        .y(rs_z$y)
    );
    vector$lanes$0$rs_z0 rs_z0(
        .x(rs_z0$x),
        .by(rs_z0$by),
        .y(rs_z0$y)
    );
    vector$lanes$0$ez0 ez0(
        .x(ez0$x),
        .y(ez0$y)
    );
    vector$lanes$0$z6 z6(
        .d(z6$d),
        .q(z6$q),
        .clock(z6$clock)
    );
    vector$lanes$0$depth_of depth_of(
        .x(depth_of$x),
        .neg(depth_of$neg),
        .over(depth_of$over),
        .low(depth_of$low)
    );
    vector$lanes$0$dtag_dl dtag_dl(
        .clock(dtag_dl$clock),
        .en(dtag_dl$en),
        .d(dtag_dl$d),
        .q(dtag_dl$q)
    );
    vector$lanes$0$rs_q$0 rs_q$0(
        .x(rs_q$0$x),
        .by(rs_q$0$by),
        .y(rs_q$0$y)
    );
    vector$lanes$0$rs_q$1 rs_q$1(
        .x(rs_q$1$x),
        .by(rs_q$1$by),
        .y(rs_q$1$y)
    );
    vector$lanes$0$rs_q$2 rs_q$2(
        .x(rs_q$2$x),
        .by(rs_q$2$by),
        .y(rs_q$2$y)
    );
    vector$lanes$0$q6$0 q6$0(
        .d(q6$0$d),
        .q(q6$0$q),
        .clock(q6$0$clock)
    );
    vector$lanes$0$q6$1 q6$1(
        .d(q6$1$d),
        .q(q6$1$q),
        .clock(q6$1$clock)
    );
    vector$lanes$0$q6$2 q6$2(
        .d(q6$2$d),
        .q(q6$2$q),
        .clock(q6$2$clock)
    );
    vector$lanes$0$eq$0 eq$0(
        .x(eq$0$x),
        .y(eq$0$y)
    );
    vector$lanes$0$eq$1 eq$1(
        .x(eq$1$x),
        .y(eq$1$y)
    );
    vector$lanes$0$eq$2 eq$2(
        .x(eq$2$x),
        .y(eq$2$y)
    );
    vector$lanes$0$sum7 sum7(
        .d(sum7$d),
        .q(sum7$q),
        .clock(sum7$clock)
    );
    vector$lanes$0$lead_s lead_s(
        .x(lead_s$x),
        .pos(lead_s$pos)
    );
    vector$lanes$0$sum8 sum8(
        .d(sum8$d),
        .q(sum8$q),
        .clock(sum8$clock)
    );
    vector$lanes$0$exp8 exp8(
        .d(exp8$d),
        .q(exp8$q),
        .clock(exp8$clock)
    );
    vector$lanes$0$q_dl q_dl(
        .clock(q_dl$clock),
        .en(q_dl$en),
        .d(q_dl$d),
        .q(q_dl$q)
    );
    vector$lanes$0$exp_dl exp_dl(
        .clock(exp_dl$clock),
        .en(exp_dl$en),
        .d(exp_dl$d),
        .q(exp_dl$q)
    );
    vector$lanes$0$ab_dl ab_dl(
        .clock(ab_dl$clock),
        .en(ab_dl$en),
        .d(ab_dl$d),
        .q(ab_dl$q)
    );
    vector$lanes$0$rs_ra rs_ra(
        .x(rs_ra$x),
        .by(rs_ra$by),
        .y(rs_ra$y)
    );
    vector$lanes$0$rs_rb rs_rb(
        .x(rs_rb$x),
        .by(rs_rb$by),
        .y(rs_rb$y)
    );
    vector$lanes$0$ca11 ca11(
        .d(ca11$d),
        .q(ca11$q),
        .clock(ca11$clock)
    );
    vector$lanes$0$cb11 cb11(
        .d(cb11$d),
        .q(cb11$q),
        .clock(cb11$clock)
    );
    vector$lanes$0$rs_c$0 rs_c$0(
        .x(rs_c$0$x),
        .by(rs_c$0$by),
        .y(rs_c$0$y)
    );
    vector$lanes$0$rs_c$1 rs_c$1(
        .x(rs_c$1$x),
        .by(rs_c$1$by),
        .y(rs_c$1$y)
    );
    vector$lanes$0$rs_c$2 rs_c$2(
        .x(rs_c$2$x),
        .by(rs_c$2$by),
        .y(rs_c$2$y)
    );
    vector$lanes$0$rs_c0$0 rs_c0$0(
        .x(rs_c0$0$x),
        .by(rs_c0$0$by),
        .y(rs_c0$0$y)
    );
    vector$lanes$0$rs_c0$1 rs_c0$1(
        .x(rs_c0$1$x),
        .by(rs_c0$1$by),
        .y(rs_c0$1$y)
    );
    vector$lanes$0$rs_c0$2 rs_c0$2(
        .x(rs_c0$2$x),
        .by(rs_c0$2$by),
        .y(rs_c0$2$y)
    );
    vector$lanes$0$c14$0 c14$0(
        .d(c14$0$d),
        .q(c14$0$q),
        .clock(c14$0$clock)
    );
    vector$lanes$0$c14$1 c14$1(
        .d(c14$1$d),
        .q(c14$1$q),
        .clock(c14$1$clock)
    );
    vector$lanes$0$c14$2 c14$2(
        .d(c14$2$d),
        .q(c14$2$q),
        .clock(c14$2$clock)
    );
    vector$lanes$0$color_of$0 color_of$0(
        .x(color_of$0$x),
        .neg(color_of$0$neg),
        .over(color_of$0$over),
        .low(color_of$0$low)
    );
    vector$lanes$0$color_of$1 color_of$1(
        .x(color_of$1$x),
        .neg(color_of$1$neg),
        .over(color_of$1$over),
        .low(color_of$1$low)
    );
    vector$lanes$0$color_of$2 color_of$2(
        .x(color_of$2$x),
        .neg(color_of$2$neg),
        .over(color_of$2$over),
        .low(color_of$2$low)
    );
    vector$lanes$0$ov ov(
        .d(ov$d),
        .q(ov$q),
        .clock(ov$clock)
    );
    vector$lanes$0$oz oz(
        .d(oz$d),
        .q(oz$q),
        .clock(oz$clock)
    );
    vector$lanes$0$orgb$0 orgb$0(
        .d(orgb$0$d),
        .q(orgb$0$q),
        .clock(orgb$0$clock)
    );
    vector$lanes$0$orgb$1 orgb$1(
        .d(orgb$1$d),
        .q(orgb$1$q),
        .clock(orgb$1$clock)
    );
    vector$lanes$0$orgb$2 orgb$2(
        .d(orgb$2$d),
        .q(orgb$2$q),
        .clock(orgb$2$clock)
    );
    
    // Update code
    always @(*) begin
        div_d$clock = clock;
        a3$clock = clock;
        b3$clock = clock;
        z6$clock = clock;
        sum7$clock = clock;
        sum8$clock = clock;
        exp8$clock = clock;
        ca11$clock = clock;
        cb11$clock = clock;
        ov$clock = clock;
        oz$clock = clock;
        div_d$d = div_d$q;
        a3$d = a3$q;
        b3$d = b3$q;
        z6$d = z6$q;
        sum7$d = sum7$q;
        sum8$d = sum8$q;
        exp8$d = exp8$q;
        ca11$d = ca11$q;
        cb11$d = cb11$q;
        ov$d = ov$q;
        oz$d = oz$q;
        div$clock = clock;
        mul_a$clock = clock;
        mul_b$clock = clock;
        mul_z1$clock = clock;
        mul_z2$clock = clock;
        mul_ra$clock = clock;
        mul_rb$clock = clock;
        hit_dl$clock = clock;
        dtag_dl$clock = clock;
        q_dl$clock = clock;
        exp_dl$clock = clock;
        ab_dl$clock = clock;
        off$0$clock = clock;
        off$0$d = off$0$q;
        q6$0$clock = clock;
        q6$0$d = q6$0$q;
        c14$0$clock = clock;
        c14$0$d = c14$0$q;
        orgb$0$clock = clock;
        orgb$0$d = orgb$0$q;
        mul_l$0$clock = clock;
        mul_c1$0$clock = clock;
        mul_c2$0$clock = clock;
        mul_l$0$en = run;
        mul_c1$0$en = run;
        mul_c2$0$en = run;
        off$1$clock = clock;
        off$1$d = off$1$q;
        q6$1$clock = clock;
        q6$1$d = q6$1$q;
        c14$1$clock = clock;
        c14$1$d = c14$1$q;
        orgb$1$clock = clock;
        orgb$1$d = orgb$1$q;
        mul_l$1$clock = clock;
        mul_c1$1$clock = clock;
        mul_c2$1$clock = clock;
        mul_l$1$en = run;
        mul_c1$1$en = run;
        mul_c2$1$en = run;
        off$2$clock = clock;
        off$2$d = off$2$q;
        q6$2$clock = clock;
        q6$2$d = q6$2$q;
        c14$2$clock = clock;
        c14$2$d = c14$2$q;
        orgb$2$clock = clock;
        orgb$2$d = orgb$2$q;
        mul_l$2$clock = clock;
        mul_c1$2$clock = clock;
        mul_c2$2$clock = clock;
        mul_l$2$en = run;
        mul_c1$2$en = run;
        mul_c2$2$en = run;
        mul_a$en = run;
        mul_b$en = run;
        mul_z1$en = run;
        mul_z2$en = run;
        mul_ra$en = run;
        mul_rb$en = run;
        hit_dl$en = run;
        dtag_dl$en = run;
        q_dl$en = run;
        exp_dl$en = run;
        ab_dl$en = run;
        div$hold = ~run;
        div$out_ready = 1'b1;
        div$inp_valid = 1'b1;
        div$inp_n = recip_n;
        g$0 = g_0;
        g$1 = g_1;
        g$2 = g_2;
        w$0 = w_0;
        w$1 = w_1;
        w$2 = w_2;
        owns$0 = owns_0;
        owns$1 = owns_1;
        owns$2 = owns_2;
        c_iw$0 = c_iw_0;
        c_iw$1 = c_iw_1;
        c_iw$2 = c_iw_2;
        c_d1c$0 = c_d1c_0;
        c_d1c$1 = c_d1c_1;
        c_d1c$2 = c_d1c_2;
        c_d2c$0 = c_d2c_0;
        c_d2c$1 = c_d2c_1;
        c_d2c$2 = c_d2c_2;
        c_c0$0 = c_c0_0;
        c_c0$1 = c_c0_1;
        c_c0$2 = c_c0_2;
        px = x + idx;
        covered = valid & (px >= x0) & (px <= x1);
        e$0 = w$0 - off$0$q;
        rej$0$e = e$0;
        rej$0$owns = owns$0;
        if (rej$0$rejects) begin
            covered = 1'b0;
        end
        e$1 = w$1 - off$1$q;
        rej$1$e = e$1;
        rej$1$owns = owns$1;
        if (rej$1$rejects) begin
            covered = 1'b0;
        end
        e$2 = w$2 - off$2$q;
        rej$2$e = e$2;
        rej$2$owns = owns$2;
        if (rej$2$rejects) begin
            covered = 1'b0;
        end
        hit = 32'h0;
        if (covered) begin
            hit = 32'h1;
        end
        hit_dl$d = hit;
        mul_a$a = e$1;
        mul_a$b = ((c_mant) & 26'h3ffffff);
        mul_b$a = e$2;
        mul_b$b = ((c_mant) & 26'h3ffffff);
        rs_a$x = mul_a$p;
        rs_a$by = c_exp;
        rs_b$x = mul_b$p;
        rs_b$by = c_exp;
        mul_z1$a = c_d1z;
        mul_z1$b = a3$q;
        mul_z2$a = c_d2z;
        mul_z2$b = b3$q;
        mul_l$0$a = one - a3$q - b3$q;
        mul_l$0$b = ((c_iw$0) & 17'h1ffff);
        mul_l$1$a = a3$q;
        mul_l$1$b = ((c_iw$1) & 17'h1ffff);
        mul_l$2$a = b3$q;
        mul_l$2$b = ((c_iw$2) & 17'h1ffff);
        ab_pair = (((a3$q) & 56'hffffffffffffff) << half_pair) | ((b3$q) & 56'hffffffffffffff);
        ab_dl$d = ab_pair;
        rs_z$x = mul_z1$p + mul_z2$p;
        rs_z$by = 32'h0;
        ez0$x = c_z0;
        rs_z0$x = ez0$y;
        rs_z0$by = 32'h0;
        rs_q$0$x = mul_l$0$p;
        rs_q$0$by = 32'h0;
        eq$0$x = q6$0$q;
        rs_q$1$x = mul_l$1$p;
        rs_q$1$by = 32'h0;
        eq$1$x = q6$1$q;
        rs_q$2$x = mul_l$2$p;
        rs_q$2$by = 32'h0;
        eq$2$x = q6$2$q;
        depth_of$x = z6$q;
        dtag = ((depth_of$low) & 17'h1ffff) << one_s;
        if (~depth_of$neg & ~depth_of$over) begin
            dtag = (((depth_of$low) & 17'h1ffff) << one_s) | 64'h1;
        end
        dtag_dl$d = dtag;
        sum_c = eq$0$y + eq$1$y + eq$2$y;
        if (sum_c == 32'h0) begin
            sum_c = 32'h1;
        end
        q_pair = (((q6$1$q) & 56'hffffffffffffff) << half_pair) | ((q6$2$q) & 56'hffffffffffffff);
        q_dl$d = q_pair;
        lead_s$x = sum7$q;
        exp_dl$d = exp8$q;
        norm_s$x = sum8$q;
        norm_s$exp = exp8$q;
        div$inp_d = div_d$q;
        mul_ra$a = ((q_dl$q >> half_pair) & 28'hfffffff);
        mul_ra$b = ((div$out_q[(32'h0)+:(25)]) & 26'h3ffffff);
        mul_rb$a = ((q_dl$q) & 28'hfffffff);
        mul_rb$b = ((div$out_q[(32'h0)+:(25)]) & 26'h3ffffff);
        rs_ra$x = mul_ra$p;
        rs_ra$by = exp_dl$q;
        rs_rb$x = mul_rb$p;
        rs_rb$by = exp_dl$q;
        ca = ((ab_dl$q >> half_pair) & 28'hfffffff);
        cb = ((ab_dl$q) & 28'hfffffff);
        if (persp$on) begin
            ca = ca11$q;
            cb = cb11$q;
        end
        rs_c0$0$x = ((c_c0$0) & 9'h1ff);
        rs_c0$1$x = ((c_c0$1) & 9'h1ff);
        rs_c0$2$x = ((c_c0$2) & 9'h1ff);
        mul_c1$0$a = c_d1c$0;
        mul_c2$0$a = c_d2c$0;
        mul_c1$0$b = ca;
        mul_c2$0$b = cb;
        rs_c$0$x = mul_c1$0$p + mul_c2$0$p;
        rs_c$0$by = 32'h0;
        rs_c0$0$by = 32'h0;
        color_of$0$x = c14$0$q;
        mul_c1$1$a = c_d1c$1;
        mul_c2$1$a = c_d2c$1;
        mul_c1$1$b = ca;
        mul_c2$1$b = cb;
        rs_c$1$x = mul_c1$1$p + mul_c2$1$p;
        rs_c$1$by = 32'h0;
        rs_c0$1$by = 32'h0;
        color_of$1$x = c14$1$q;
        mul_c1$2$a = c_d1c$2;
        mul_c2$2$a = c_d2c$2;
        mul_c1$2$b = ca;
        mul_c2$2$b = cb;
        rs_c$2$x = mul_c1$2$p + mul_c2$2$p;
        rs_c$2$by = 32'h0;
        rs_c0$2$by = 32'h0;
        color_of$2$x = c14$2$q;
        if (run) begin
            if (load) begin
                off$0$d = (g$0 & m1) + ((g$0 << one_s) & m2) + ((g$0 << two_s) & m4);
                off$1$d = (g$1 & m1) + ((g$1 << one_s) & m2) + ((g$1 << two_s) & m4);
                off$2$d = (g$2 & m1) + ((g$2 << one_s) & m2) + ((g$2 << two_s) & m4);
            end
            a3$d = rs_a$y;
            b3$d = rs_b$y;
            z6$d = rs_z$y + rs_z0$y;
            q6$0$d = rs_q$0$y;
            c14$0$d = rs_c$0$y + rs_c0$0$y;
            orgb$0$d = color_of$0$low;
            if (color_of$0$over) begin
                orgb$0$d = full;
            end
            if (color_of$0$neg) begin
                orgb$0$d = 32'h0;
            end
            q6$1$d = rs_q$1$y;
            c14$1$d = rs_c$1$y + rs_c0$1$y;
            orgb$1$d = color_of$1$low;
            if (color_of$1$over) begin
                orgb$1$d = full;
            end
            if (color_of$1$neg) begin
                orgb$1$d = 32'h0;
            end
            q6$2$d = rs_q$2$y;
            c14$2$d = rs_c$2$y + rs_c0$2$y;
            orgb$2$d = color_of$2$low;
            if (color_of$2$over) begin
                orgb$2$d = full;
            end
            if (color_of$2$neg) begin
                orgb$2$d = 32'h0;
            end
            div_d$d = norm_s$d;
            sum7$d = sum_c;
            sum8$d = sum7$q;
            exp8$d = lead_s$pos;
            ca11$d = rs_ra$y;
            cb11$d = rs_rb$y;
            ov$d = (hit_dl$q != 32'h0) & dtag_dl$q[32'h0];
            oz$d = ((dtag_dl$q >> one_s) & 16'hffff);
        end
        o_valid = ov$q;
        o_z = oz$q;
        o_rgb = (((orgb$0$q) & 24'hffffff) << ch2) | (((orgb$1$q) & 24'hffffff) << ch1) | ((orgb$2$q) & 24'hffffff);
    end
    
endmodule // vector$lanes$0


module vector$lanes$0$a3(d,q,clock);
    
    // Module arguments
    input wire  [27:0] d;
    output reg  [27:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 28'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$a3


module vector$lanes$0$ab_dl(clock,en,d,q);
    
    // Module arguments
    input wire  clock;
    input wire  en;
    input wire  [55:0] d;
    output reg  [55:0] q;
    
    // Stub signals
    reg  [55:0] stages$0$d;
    wire  [55:0] stages$0$q;
    reg  stages$0$clock;
    reg  [55:0] stages$1$d;
    wire  [55:0] stages$1$q;
    reg  stages$1$clock;
    reg  [55:0] stages$2$d;
    wire  [55:0] stages$2$q;
    reg  stages$2$clock;
    reg  [55:0] stages$3$d;
    wire  [55:0] stages$3$q;
    reg  stages$3$clock;
    reg  [55:0] stages$4$d;
    wire  [55:0] stages$4$q;
    reg  stages$4$clock;
    reg  [55:0] stages$5$d;
    wire  [55:0] stages$5$q;
    reg  stages$5$clock;
    reg  [55:0] stages$6$d;
    wire  [55:0] stages$6$q;
    reg  stages$6$clock;
    reg  [55:0] stages$7$d;
    wire  [55:0] stages$7$q;
    reg  stages$7$clock;
    reg  [55:0] stages$8$d;
    wire  [55:0] stages$8$q;
    reg  stages$8$clock;
    reg  [55:0] stages$9$d;
    wire  [55:0] stages$9$q;
    reg  stages$9$clock;
    reg  [55:0] stages$10$d;
    wire  [55:0] stages$10$q;
    reg  stages$10$clock;
    reg  [55:0] stages$11$d;
    wire  [55:0] stages$11$q;
    reg  stages$11$clock;
    reg  [55:0] stages$12$d;
    wire  [55:0] stages$12$q;
    reg  stages$12$clock;
    reg  [55:0] stages$13$d;
    wire  [55:0] stages$13$q;
    reg  stages$13$clock;
    reg  [55:0] stages$14$d;
    wire  [55:0] stages$14$q;
    reg  stages$14$clock;
    reg  [55:0] stages$15$d;
    wire  [55:0] stages$15$q;
    reg  stages$15$clock;
    reg  [55:0] stages$16$d;
    wire  [55:0] stages$16$q;
    reg  stages$16$clock;
    reg  [55:0] stages$17$d;
    wire  [55:0] stages$17$q;
    reg  stages$17$clock;
    reg  [55:0] stages$18$d;
    wire  [55:0] stages$18$q;
    reg  stages$18$clock;
    reg  [55:0] stages$19$d;
    wire  [55:0] stages$19$q;
    reg  stages$19$clock;
    reg  [55:0] stages$20$d;
    wire  [55:0] stages$20$q;
    reg  stages$20$clock;
    reg  [55:0] stages$21$d;
    wire  [55:0] stages$21$q;
    reg  stages$21$clock;
    reg  [55:0] stages$22$d;
    wire  [55:0] stages$22$q;
    reg  stages$22$clock;
    reg  [55:0] stages$23$d;
    wire  [55:0] stages$23$q;
    reg  stages$23$clock;
    reg  [55:0] stages$24$d;
    wire  [55:0] stages$24$q;
    reg  stages$24$clock;
    reg  [55:0] stages$25$d;
    wire  [55:0] stages$25$q;
    reg  stages$25$clock;
    reg  [55:0] stages$26$d;
    wire  [55:0] stages$26$q;
    reg  stages$26$clock;
    reg  [55:0] stages$27$d;
    wire  [55:0] stages$27$q;
    reg  stages$27$clock;
    reg  [55:0] stages$28$d;
    wire  [55:0] stages$28$q;
    reg  stages$28$clock;
    reg  [55:0] stages$29$d;
    wire  [55:0] stages$29$q;
    reg  stages$29$clock;
    reg  [55:0] stages$30$d;
    wire  [55:0] stages$30$q;
    reg  stages$30$clock;
    reg  [55:0] stages$31$d;
    wire  [55:0] stages$31$q;
    reg  stages$31$clock;
    reg  [55:0] stages$32$d;
    wire  [55:0] stages$32$q;
    reg  stages$32$clock;
    reg  [55:0] stages$33$d;
    wire  [55:0] stages$33$q;
    reg  stages$33$clock;
    
    // Sub module instances
    vector$lanes$0$ab_dl$stages$0 stages$0(
        .d(stages$0$d),
        .q(stages$0$q),
        .clock(stages$0$clock)
    );
    vector$lanes$0$ab_dl$stages$1 stages$1(
        .d(stages$1$d),
        .q(stages$1$q),
        .clock(stages$1$clock)
    );
    vector$lanes$0$ab_dl$stages$2 stages$2(
        .d(stages$2$d),
        .q(stages$2$q),
        .clock(stages$2$clock)
    );
    vector$lanes$0$ab_dl$stages$3 stages$3(
        .d(stages$3$d),
        .q(stages$3$q),
        .clock(stages$3$clock)
    );
    vector$lanes$0$ab_dl$stages$4 stages$4(
        .d(stages$4$d),
        .q(stages$4$q),
        .clock(stages$4$clock)
    );
    vector$lanes$0$ab_dl$stages$5 stages$5(
        .d(stages$5$d),
        .q(stages$5$q),
        .clock(stages$5$clock)
    );
    vector$lanes$0$ab_dl$stages$6 stages$6(
        .d(stages$6$d),
        .q(stages$6$q),
        .clock(stages$6$clock)
    );
    vector$lanes$0$ab_dl$stages$7 stages$7(
        .d(stages$7$d),
        .q(stages$7$q),
        .clock(stages$7$clock)
    );
    vector$lanes$0$ab_dl$stages$8 stages$8(
        .d(stages$8$d),
        .q(stages$8$q),
        .clock(stages$8$clock)
    );
    vector$lanes$0$ab_dl$stages$9 stages$9(
        .d(stages$9$d),
        .q(stages$9$q),
        .clock(stages$9$clock)
    );
    vector$lanes$0$ab_dl$stages$10 stages$10(
        .d(stages$10$d),
        .q(stages$10$q),
        .clock(stages$10$clock)
    );
    vector$lanes$0$ab_dl$stages$11 stages$11(
        .d(stages$11$d),
        .q(stages$11$q),
        .clock(stages$11$clock)
    );
    vector$lanes$0$ab_dl$stages$12 stages$12(
        .d(stages$12$d),
        .q(stages$12$q),
        .clock(stages$12$clock)
    );
    vector$lanes$0$ab_dl$stages$13 stages$13(
        .d(stages$13$d),
        .q(stages$13$q),
        .clock(stages$13$clock)
    );
    vector$lanes$0$ab_dl$stages$14 stages$14(
        .d(stages$14$d),
        .q(stages$14$q),
        .clock(stages$14$clock)
    );
    vector$lanes$0$ab_dl$stages$15 stages$15(
        .d(stages$15$d),
        .q(stages$15$q),
        .clock(stages$15$clock)
    );
    vector$lanes$0$ab_dl$stages$16 stages$16(
        .d(stages$16$d),
        .q(stages$16$q),
        .clock(stages$16$clock)
    );
    vector$lanes$0$ab_dl$stages$17 stages$17(
        .d(stages$17$d),
        .q(stages$17$q),
        .clock(stages$17$clock)
    );
    vector$lanes$0$ab_dl$stages$18 stages$18(
        .d(stages$18$d),
        .q(stages$18$q),
        .clock(stages$18$clock)
    );
    vector$lanes$0$ab_dl$stages$19 stages$19(
        .d(stages$19$d),
        .q(stages$19$q),
        .clock(stages$19$clock)
    );
    vector$lanes$0$ab_dl$stages$20 stages$20(
        .d(stages$20$d),
        .q(stages$20$q),
        .clock(stages$20$clock)
    );
    vector$lanes$0$ab_dl$stages$21 stages$21(
        .d(stages$21$d),
        .q(stages$21$q),
        .clock(stages$21$clock)
    );
    vector$lanes$0$ab_dl$stages$22 stages$22(
        .d(stages$22$d),
        .q(stages$22$q),
        .clock(stages$22$clock)
    );
    vector$lanes$0$ab_dl$stages$23 stages$23(
        .d(stages$23$d),
        .q(stages$23$q),
        .clock(stages$23$clock)
    );
    vector$lanes$0$ab_dl$stages$24 stages$24(
        .d(stages$24$d),
        .q(stages$24$q),
        .clock(stages$24$clock)
    );
    vector$lanes$0$ab_dl$stages$25 stages$25(
        .d(stages$25$d),
        .q(stages$25$q),
        .clock(stages$25$clock)
    );
    vector$lanes$0$ab_dl$stages$26 stages$26(
        .d(stages$26$d),
        .q(stages$26$q),
        .clock(stages$26$clock)
    );
    vector$lanes$0$ab_dl$stages$27 stages$27(
        .d(stages$27$d),
        .q(stages$27$q),
        .clock(stages$27$clock)
    );
    vector$lanes$0$ab_dl$stages$28 stages$28(
        .d(stages$28$d),
        .q(stages$28$q),
        .clock(stages$28$clock)
    );
    vector$lanes$0$ab_dl$stages$29 stages$29(
        .d(stages$29$d),
        .q(stages$29$q),
        .clock(stages$29$clock)
    );
    vector$lanes$0$ab_dl$stages$30 stages$30(
        .d(stages$30$d),
        .q(stages$30$q),
        .clock(stages$30$clock)
    );
    vector$lanes$0$ab_dl$stages$31 stages$31(
        .d(stages$31$d),
        .q(stages$31$q),
        .clock(stages$31$clock)
    );
    vector$lanes$0$ab_dl$stages$32 stages$32(
        .d(stages$32$d),
        .q(stages$32$q),
        .clock(stages$32$clock)
    );
    vector$lanes$0$ab_dl$stages$33 stages$33(
        .d(stages$33$d),
        .q(stages$33$q),
        .clock(stages$33$clock)
    );
    
    // Update code
    always @(*) begin
        stages$0$clock = clock;
        stages$0$d = stages$0$q;
        stages$1$clock = clock;
        stages$1$d = stages$1$q;
        stages$2$clock = clock;
        stages$2$d = stages$2$q;
        stages$3$clock = clock;
        stages$3$d = stages$3$q;
        stages$4$clock = clock;
        stages$4$d = stages$4$q;
        stages$5$clock = clock;
        stages$5$d = stages$5$q;
        stages$6$clock = clock;
        stages$6$d = stages$6$q;
        stages$7$clock = clock;
        stages$7$d = stages$7$q;
        stages$8$clock = clock;
        stages$8$d = stages$8$q;
        stages$9$clock = clock;
        stages$9$d = stages$9$q;
        stages$10$clock = clock;
        stages$10$d = stages$10$q;
        stages$11$clock = clock;
        stages$11$d = stages$11$q;
        stages$12$clock = clock;
        stages$12$d = stages$12$q;
        stages$13$clock = clock;
        stages$13$d = stages$13$q;
        stages$14$clock = clock;
        stages$14$d = stages$14$q;
        stages$15$clock = clock;
        stages$15$d = stages$15$q;
        stages$16$clock = clock;
        stages$16$d = stages$16$q;
        stages$17$clock = clock;
        stages$17$d = stages$17$q;
        stages$18$clock = clock;
        stages$18$d = stages$18$q;
        stages$19$clock = clock;
        stages$19$d = stages$19$q;
        stages$20$clock = clock;
        stages$20$d = stages$20$q;
        stages$21$clock = clock;
        stages$21$d = stages$21$q;
        stages$22$clock = clock;
        stages$22$d = stages$22$q;
        stages$23$clock = clock;
        stages$23$d = stages$23$q;
        stages$24$clock = clock;
        stages$24$d = stages$24$q;
        stages$25$clock = clock;
        stages$25$d = stages$25$q;
        stages$26$clock = clock;
        stages$26$d = stages$26$q;
        stages$27$clock = clock;
        stages$27$d = stages$27$q;
        stages$28$clock = clock;
        stages$28$d = stages$28$q;
        stages$29$clock = clock;
        stages$29$d = stages$29$q;
        stages$30$clock = clock;
        stages$30$d = stages$30$q;
        stages$31$clock = clock;
        stages$31$d = stages$31$q;
        stages$32$clock = clock;
        stages$32$d = stages$32$q;
        stages$33$clock = clock;
        stages$33$d = stages$33$q;
        if (en) begin
            stages$0$d = d;
            stages$1$d = stages$0$q;
            stages$2$d = stages$1$q;
            stages$3$d = stages$2$q;
            stages$4$d = stages$3$q;
            stages$5$d = stages$4$q;
            stages$6$d = stages$5$q;
            stages$7$d = stages$6$q;
            stages$8$d = stages$7$q;
            stages$9$d = stages$8$q;
            stages$10$d = stages$9$q;
            stages$11$d = stages$10$q;
            stages$12$d = stages$11$q;
            stages$13$d = stages$12$q;
            stages$14$d = stages$13$q;
            stages$15$d = stages$14$q;
            stages$16$d = stages$15$q;
            stages$17$d = stages$16$q;
            stages$18$d = stages$17$q;
            stages$19$d = stages$18$q;
            stages$20$d = stages$19$q;
            stages$21$d = stages$20$q;
            stages$22$d = stages$21$q;
            stages$23$d = stages$22$q;
            stages$24$d = stages$23$q;
            stages$25$d = stages$24$q;
            stages$26$d = stages$25$q;
            stages$27$d = stages$26$q;
            stages$28$d = stages$27$q;
            stages$29$d = stages$28$q;
            stages$30$d = stages$29$q;
            stages$31$d = stages$30$q;
            stages$32$d = stages$31$q;
            stages$33$d = stages$32$q;
        end
        q = stages$33$q;
    end
    
endmodule // vector$lanes$0$ab_dl


module vector$lanes$0$ab_dl$stages$0(d,q,clock);
    
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
          
endmodule // vector$lanes$0$ab_dl$stages$0


module vector$lanes$0$ab_dl$stages$1(d,q,clock);
    
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
          
endmodule // vector$lanes$0$ab_dl$stages$1


module vector$lanes$0$ab_dl$stages$10(d,q,clock);
    
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
          
endmodule // vector$lanes$0$ab_dl$stages$10


module vector$lanes$0$ab_dl$stages$11(d,q,clock);
    
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
          
endmodule // vector$lanes$0$ab_dl$stages$11


module vector$lanes$0$ab_dl$stages$12(d,q,clock);
    
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
          
endmodule // vector$lanes$0$ab_dl$stages$12


module vector$lanes$0$ab_dl$stages$13(d,q,clock);
    
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
          
endmodule // vector$lanes$0$ab_dl$stages$13


module vector$lanes$0$ab_dl$stages$14(d,q,clock);
    
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
          
endmodule // vector$lanes$0$ab_dl$stages$14


module vector$lanes$0$ab_dl$stages$15(d,q,clock);
    
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
          
endmodule // vector$lanes$0$ab_dl$stages$15


module vector$lanes$0$ab_dl$stages$16(d,q,clock);
    
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
          
endmodule // vector$lanes$0$ab_dl$stages$16


module vector$lanes$0$ab_dl$stages$17(d,q,clock);
    
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
          
endmodule // vector$lanes$0$ab_dl$stages$17


module vector$lanes$0$ab_dl$stages$18(d,q,clock);
    
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
          
endmodule // vector$lanes$0$ab_dl$stages$18


module vector$lanes$0$ab_dl$stages$19(d,q,clock);
    
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
          
endmodule // vector$lanes$0$ab_dl$stages$19


module vector$lanes$0$ab_dl$stages$2(d,q,clock);
    
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
          
endmodule // vector$lanes$0$ab_dl$stages$2


module vector$lanes$0$ab_dl$stages$20(d,q,clock);
    
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
          
endmodule // vector$lanes$0$ab_dl$stages$20


module vector$lanes$0$ab_dl$stages$21(d,q,clock);
    
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
          
endmodule // vector$lanes$0$ab_dl$stages$21


module vector$lanes$0$ab_dl$stages$22(d,q,clock);
    
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
          
endmodule // vector$lanes$0$ab_dl$stages$22


module vector$lanes$0$ab_dl$stages$23(d,q,clock);
    
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
          
endmodule // vector$lanes$0$ab_dl$stages$23


module vector$lanes$0$ab_dl$stages$24(d,q,clock);
    
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
          
endmodule // vector$lanes$0$ab_dl$stages$24


module vector$lanes$0$ab_dl$stages$25(d,q,clock);
    
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
          
endmodule // vector$lanes$0$ab_dl$stages$25


module vector$lanes$0$ab_dl$stages$26(d,q,clock);
    
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
          
endmodule // vector$lanes$0$ab_dl$stages$26


module vector$lanes$0$ab_dl$stages$27(d,q,clock);
    
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
          
endmodule // vector$lanes$0$ab_dl$stages$27


module vector$lanes$0$ab_dl$stages$28(d,q,clock);
    
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
          
endmodule // vector$lanes$0$ab_dl$stages$28


module vector$lanes$0$ab_dl$stages$29(d,q,clock);
    
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
          
endmodule // vector$lanes$0$ab_dl$stages$29


module vector$lanes$0$ab_dl$stages$3(d,q,clock);
    
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
          
endmodule // vector$lanes$0$ab_dl$stages$3


module vector$lanes$0$ab_dl$stages$30(d,q,clock);
    
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
          
endmodule // vector$lanes$0$ab_dl$stages$30


module vector$lanes$0$ab_dl$stages$31(d,q,clock);
    
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
          
endmodule // vector$lanes$0$ab_dl$stages$31


module vector$lanes$0$ab_dl$stages$32(d,q,clock);
    
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
          
endmodule // vector$lanes$0$ab_dl$stages$32


module vector$lanes$0$ab_dl$stages$33(d,q,clock);
    
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
          
endmodule // vector$lanes$0$ab_dl$stages$33


module vector$lanes$0$ab_dl$stages$4(d,q,clock);
    
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
          
endmodule // vector$lanes$0$ab_dl$stages$4


module vector$lanes$0$ab_dl$stages$5(d,q,clock);
    
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
          
endmodule // vector$lanes$0$ab_dl$stages$5


module vector$lanes$0$ab_dl$stages$6(d,q,clock);
    
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
          
endmodule // vector$lanes$0$ab_dl$stages$6


module vector$lanes$0$ab_dl$stages$7(d,q,clock);
    
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
          
endmodule // vector$lanes$0$ab_dl$stages$7


module vector$lanes$0$ab_dl$stages$8(d,q,clock);
    
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
          
endmodule // vector$lanes$0$ab_dl$stages$8


module vector$lanes$0$ab_dl$stages$9(d,q,clock);
    
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
          
endmodule // vector$lanes$0$ab_dl$stages$9


module vector$lanes$0$b3(d,q,clock);
    
    // Module arguments
    input wire  [27:0] d;
    output reg  [27:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 28'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$b3


module vector$lanes$0$c14$0(d,q,clock);
    
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
          
endmodule // vector$lanes$0$c14$0


module vector$lanes$0$c14$1(d,q,clock);
    
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
          
endmodule // vector$lanes$0$c14$1


module vector$lanes$0$c14$2(d,q,clock);
    
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
          
endmodule // vector$lanes$0$c14$2


module vector$lanes$0$ca11(d,q,clock);
    
    // Module arguments
    input wire  [27:0] d;
    output reg  [27:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 28'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$ca11


module vector$lanes$0$cb11(d,q,clock);
    
    // Module arguments
    input wire  [27:0] d;
    output reg  [27:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 28'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$cb11


module vector$lanes$0$color_of$0(x,neg,over,low);
    
    // Module arguments
    input wire  [31:0] x;
    output reg  neg;
    output reg  over;
    output reg  [7:0] low;
    
    // Constant declarations
    localparam  top = 33'h100000000;
    localparam  half = 33'h200000;
    localparam  shift = 8'h16;
    localparam  limit = 33'h100;
    
    // Stub signals
    reg  [31:0] x_neg$x;
    wire  x_neg$neg;
    
    // Local signals
    reg  [32:0] ext;
    reg  [32:0] sum;
    reg  [32:0] shifted;
    
    // Sub module instances
    vector$lanes$0$color_of$0$x_neg x_neg(
        .x(x_neg$x),
        .neg(x_neg$neg)
    );
    
    // Update code
    always @(*) begin
        x_neg$x = x;
        ext = ((x) & 33'h1ffffffff);
        if (x_neg$neg) begin
            ext = ((x) & 33'h1ffffffff) | top;
        end
        sum = ext + half;
        neg = sum >= top;
        shifted = sum >> shift;
        over = ~neg & (shifted >= limit);
        low = ((shifted) & 8'hff);
    end
    
endmodule // vector$lanes$0$color_of$0


module vector$lanes$0$color_of$0$x_neg(x,neg);
    
    // Module arguments
    input wire  [31:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 32'h80000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // vector$lanes$0$color_of$0$x_neg


module vector$lanes$0$color_of$1(x,neg,over,low);
    
    // Module arguments
    input wire  [31:0] x;
    output reg  neg;
    output reg  over;
    output reg  [7:0] low;
    
    // Constant declarations
    localparam  top = 33'h100000000;
    localparam  half = 33'h200000;
    localparam  shift = 8'h16;
    localparam  limit = 33'h100;
    
    // Stub signals
    reg  [31:0] x_neg$x;
    wire  x_neg$neg;
    
    // Local signals
    reg  [32:0] ext;
    reg  [32:0] sum;
    reg  [32:0] shifted;
    
    // Sub module instances
    vector$lanes$0$color_of$1$x_neg x_neg(
        .x(x_neg$x),
        .neg(x_neg$neg)
    );
    
    // Update code
    always @(*) begin
        x_neg$x = x;
        ext = ((x) & 33'h1ffffffff);
        if (x_neg$neg) begin
            ext = ((x) & 33'h1ffffffff) | top;
        end
        sum = ext + half;
        neg = sum >= top;
        shifted = sum >> shift;
        over = ~neg & (shifted >= limit);
        low = ((shifted) & 8'hff);
    end
    
endmodule // vector$lanes$0$color_of$1


module vector$lanes$0$color_of$1$x_neg(x,neg);
    
    // Module arguments
    input wire  [31:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 32'h80000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // vector$lanes$0$color_of$1$x_neg


module vector$lanes$0$color_of$2(x,neg,over,low);
    
    // Module arguments
    input wire  [31:0] x;
    output reg  neg;
    output reg  over;
    output reg  [7:0] low;
    
    // Constant declarations
    localparam  top = 33'h100000000;
    localparam  half = 33'h200000;
    localparam  shift = 8'h16;
    localparam  limit = 33'h100;
    
    // Stub signals
    reg  [31:0] x_neg$x;
    wire  x_neg$neg;
    
    // Local signals
    reg  [32:0] ext;
    reg  [32:0] sum;
    reg  [32:0] shifted;
    
    // Sub module instances
    vector$lanes$0$color_of$2$x_neg x_neg(
        .x(x_neg$x),
        .neg(x_neg$neg)
    );
    
    // Update code
    always @(*) begin
        x_neg$x = x;
        ext = ((x) & 33'h1ffffffff);
        if (x_neg$neg) begin
            ext = ((x) & 33'h1ffffffff) | top;
        end
        sum = ext + half;
        neg = sum >= top;
        shifted = sum >> shift;
        over = ~neg & (shifted >= limit);
        low = ((shifted) & 8'hff);
    end
    
endmodule // vector$lanes$0$color_of$2


module vector$lanes$0$color_of$2$x_neg(x,neg);
    
    // Module arguments
    input wire  [31:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 32'h80000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // vector$lanes$0$color_of$2$x_neg


module vector$lanes$0$depth_of(x,neg,over,low);
    
    // Module arguments
    input wire  [35:0] x;
    output reg  neg;
    output reg  over;
    output reg  [15:0] low;
    
    // Constant declarations
    localparam  top = 37'h1000000000;
    localparam  half = 37'h20000;
    localparam  shift = 8'h12;
    localparam  limit = 37'h10000;
    
    // Stub signals
    reg  [35:0] x_neg$x;
    wire  x_neg$neg;
    
    // Local signals
    reg  [36:0] ext;
    reg  [36:0] sum;
    reg  [36:0] shifted;
    
    // Sub module instances
    vector$lanes$0$depth_of$x_neg x_neg(
        .x(x_neg$x),
        .neg(x_neg$neg)
    );
    
    // Update code
    always @(*) begin
        x_neg$x = x;
        ext = ((x) & 37'h1fffffffff);
        if (x_neg$neg) begin
            ext = ((x) & 37'h1fffffffff) | top;
        end
        sum = ext + half;
        neg = sum >= top;
        shifted = sum >> shift;
        over = ~neg & (shifted >= limit);
        low = ((shifted) & 16'hffff);
    end
    
endmodule // vector$lanes$0$depth_of


module vector$lanes$0$depth_of$x_neg(x,neg);
    
    // Module arguments
    input wire  [35:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 36'h800000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // vector$lanes$0$depth_of$x_neg


module vector$lanes$0$div(clock,inp_valid,inp_ready,hold,inp_n,inp_d,out_valid,out_ready,out_q,out_r);
    
    // Module arguments
    input wire  clock;
    input wire  inp_valid;
    output reg  inp_ready;
    input wire  hold;
    input wire  [57:0] inp_n;
    input wire  [33:0] inp_d;
    output reg  out_valid;
    input wire  out_ready;
    output reg  [25:0] out_q;
    output reg  [33:0] out_r;
    
    // Constant declarations
    localparam  n_msb = 8'h39;
    localparam  qm = 8'h19;
    localparam  q_sign = 26'h2000000;
    
    // Stub signals
    reg  stages$0$clock;
    reg  stages$0$enable;
    reg  stages$0$valid_in;
    reg  [33:0] stages$0$p_in;
    reg  [24:0] stages$0$x_in;
    reg  [33:0] stages$0$d_in;
    reg  stages$0$neg_in;
    wire  stages$0$valid;
    wire  [33:0] stages$0$p;
    wire  [24:0] stages$0$x;
    wire  [33:0] stages$0$d;
    wire  stages$0$neg;
    reg  stages$1$clock;
    reg  stages$1$enable;
    reg  stages$1$valid_in;
    reg  [33:0] stages$1$p_in;
    reg  [24:0] stages$1$x_in;
    reg  [33:0] stages$1$d_in;
    reg  stages$1$neg_in;
    wire  stages$1$valid;
    wire  [33:0] stages$1$p;
    wire  [24:0] stages$1$x;
    wire  [33:0] stages$1$d;
    wire  stages$1$neg;
    reg  stages$2$clock;
    reg  stages$2$enable;
    reg  stages$2$valid_in;
    reg  [33:0] stages$2$p_in;
    reg  [24:0] stages$2$x_in;
    reg  [33:0] stages$2$d_in;
    reg  stages$2$neg_in;
    wire  stages$2$valid;
    wire  [33:0] stages$2$p;
    wire  [24:0] stages$2$x;
    wire  [33:0] stages$2$d;
    wire  stages$2$neg;
    reg  stages$3$clock;
    reg  stages$3$enable;
    reg  stages$3$valid_in;
    reg  [33:0] stages$3$p_in;
    reg  [24:0] stages$3$x_in;
    reg  [33:0] stages$3$d_in;
    reg  stages$3$neg_in;
    wire  stages$3$valid;
    wire  [33:0] stages$3$p;
    wire  [24:0] stages$3$x;
    wire  [33:0] stages$3$d;
    wire  stages$3$neg;
    reg  stages$4$clock;
    reg  stages$4$enable;
    reg  stages$4$valid_in;
    reg  [33:0] stages$4$p_in;
    reg  [24:0] stages$4$x_in;
    reg  [33:0] stages$4$d_in;
    reg  stages$4$neg_in;
    wire  stages$4$valid;
    wire  [33:0] stages$4$p;
    wire  [24:0] stages$4$x;
    wire  [33:0] stages$4$d;
    wire  stages$4$neg;
    reg  stages$5$clock;
    reg  stages$5$enable;
    reg  stages$5$valid_in;
    reg  [33:0] stages$5$p_in;
    reg  [24:0] stages$5$x_in;
    reg  [33:0] stages$5$d_in;
    reg  stages$5$neg_in;
    wire  stages$5$valid;
    wire  [33:0] stages$5$p;
    wire  [24:0] stages$5$x;
    wire  [33:0] stages$5$d;
    wire  stages$5$neg;
    reg  stages$6$clock;
    reg  stages$6$enable;
    reg  stages$6$valid_in;
    reg  [33:0] stages$6$p_in;
    reg  [24:0] stages$6$x_in;
    reg  [33:0] stages$6$d_in;
    reg  stages$6$neg_in;
    wire  stages$6$valid;
    wire  [33:0] stages$6$p;
    wire  [24:0] stages$6$x;
    wire  [33:0] stages$6$d;
    wire  stages$6$neg;
    reg  stages$7$clock;
    reg  stages$7$enable;
    reg  stages$7$valid_in;
    reg  [33:0] stages$7$p_in;
    reg  [24:0] stages$7$x_in;
    reg  [33:0] stages$7$d_in;
    reg  stages$7$neg_in;
    wire  stages$7$valid;
    wire  [33:0] stages$7$p;
    wire  [24:0] stages$7$x;
    wire  [33:0] stages$7$d;
    wire  stages$7$neg;
    reg  stages$8$clock;
    reg  stages$8$enable;
    reg  stages$8$valid_in;
    reg  [33:0] stages$8$p_in;
    reg  [24:0] stages$8$x_in;
    reg  [33:0] stages$8$d_in;
    reg  stages$8$neg_in;
    wire  stages$8$valid;
    wire  [33:0] stages$8$p;
    wire  [24:0] stages$8$x;
    wire  [33:0] stages$8$d;
    wire  stages$8$neg;
    reg  stages$9$clock;
    reg  stages$9$enable;
    reg  stages$9$valid_in;
    reg  [33:0] stages$9$p_in;
    reg  [24:0] stages$9$x_in;
    reg  [33:0] stages$9$d_in;
    reg  stages$9$neg_in;
    wire  stages$9$valid;
    wire  [33:0] stages$9$p;
    wire  [24:0] stages$9$x;
    wire  [33:0] stages$9$d;
    wire  stages$9$neg;
    reg  stages$10$clock;
    reg  stages$10$enable;
    reg  stages$10$valid_in;
    reg  [33:0] stages$10$p_in;
    reg  [24:0] stages$10$x_in;
    reg  [33:0] stages$10$d_in;
    reg  stages$10$neg_in;
    wire  stages$10$valid;
    wire  [33:0] stages$10$p;
    wire  [24:0] stages$10$x;
    wire  [33:0] stages$10$d;
    wire  stages$10$neg;
    reg  stages$11$clock;
    reg  stages$11$enable;
    reg  stages$11$valid_in;
    reg  [33:0] stages$11$p_in;
    reg  [24:0] stages$11$x_in;
    reg  [33:0] stages$11$d_in;
    reg  stages$11$neg_in;
    wire  stages$11$valid;
    wire  [33:0] stages$11$p;
    wire  [24:0] stages$11$x;
    wire  [33:0] stages$11$d;
    wire  stages$11$neg;
    reg  stages$12$clock;
    reg  stages$12$enable;
    reg  stages$12$valid_in;
    reg  [33:0] stages$12$p_in;
    reg  [24:0] stages$12$x_in;
    reg  [33:0] stages$12$d_in;
    reg  stages$12$neg_in;
    wire  stages$12$valid;
    wire  [33:0] stages$12$p;
    wire  [24:0] stages$12$x;
    wire  [33:0] stages$12$d;
    wire  stages$12$neg;
    reg  stages$13$clock;
    reg  stages$13$enable;
    reg  stages$13$valid_in;
    reg  [33:0] stages$13$p_in;
    reg  [24:0] stages$13$x_in;
    reg  [33:0] stages$13$d_in;
    reg  stages$13$neg_in;
    wire  stages$13$valid;
    wire  [33:0] stages$13$p;
    wire  [24:0] stages$13$x;
    wire  [33:0] stages$13$d;
    wire  stages$13$neg;
    reg  stages$14$clock;
    reg  stages$14$enable;
    reg  stages$14$valid_in;
    reg  [33:0] stages$14$p_in;
    reg  [24:0] stages$14$x_in;
    reg  [33:0] stages$14$d_in;
    reg  stages$14$neg_in;
    wire  stages$14$valid;
    wire  [33:0] stages$14$p;
    wire  [24:0] stages$14$x;
    wire  [33:0] stages$14$d;
    wire  stages$14$neg;
    reg  stages$15$clock;
    reg  stages$15$enable;
    reg  stages$15$valid_in;
    reg  [33:0] stages$15$p_in;
    reg  [24:0] stages$15$x_in;
    reg  [33:0] stages$15$d_in;
    reg  stages$15$neg_in;
    wire  stages$15$valid;
    wire  [33:0] stages$15$p;
    wire  [24:0] stages$15$x;
    wire  [33:0] stages$15$d;
    wire  stages$15$neg;
    reg  stages$16$clock;
    reg  stages$16$enable;
    reg  stages$16$valid_in;
    reg  [33:0] stages$16$p_in;
    reg  [24:0] stages$16$x_in;
    reg  [33:0] stages$16$d_in;
    reg  stages$16$neg_in;
    wire  stages$16$valid;
    wire  [33:0] stages$16$p;
    wire  [24:0] stages$16$x;
    wire  [33:0] stages$16$d;
    wire  stages$16$neg;
    reg  stages$17$clock;
    reg  stages$17$enable;
    reg  stages$17$valid_in;
    reg  [33:0] stages$17$p_in;
    reg  [24:0] stages$17$x_in;
    reg  [33:0] stages$17$d_in;
    reg  stages$17$neg_in;
    wire  stages$17$valid;
    wire  [33:0] stages$17$p;
    wire  [24:0] stages$17$x;
    wire  [33:0] stages$17$d;
    wire  stages$17$neg;
    reg  stages$18$clock;
    reg  stages$18$enable;
    reg  stages$18$valid_in;
    reg  [33:0] stages$18$p_in;
    reg  [24:0] stages$18$x_in;
    reg  [33:0] stages$18$d_in;
    reg  stages$18$neg_in;
    wire  stages$18$valid;
    wire  [33:0] stages$18$p;
    wire  [24:0] stages$18$x;
    wire  [33:0] stages$18$d;
    wire  stages$18$neg;
    reg  stages$19$clock;
    reg  stages$19$enable;
    reg  stages$19$valid_in;
    reg  [33:0] stages$19$p_in;
    reg  [24:0] stages$19$x_in;
    reg  [33:0] stages$19$d_in;
    reg  stages$19$neg_in;
    wire  stages$19$valid;
    wire  [33:0] stages$19$p;
    wire  [24:0] stages$19$x;
    wire  [33:0] stages$19$d;
    wire  stages$19$neg;
    reg  stages$20$clock;
    reg  stages$20$enable;
    reg  stages$20$valid_in;
    reg  [33:0] stages$20$p_in;
    reg  [24:0] stages$20$x_in;
    reg  [33:0] stages$20$d_in;
    reg  stages$20$neg_in;
    wire  stages$20$valid;
    wire  [33:0] stages$20$p;
    wire  [24:0] stages$20$x;
    wire  [33:0] stages$20$d;
    wire  stages$20$neg;
    reg  stages$21$clock;
    reg  stages$21$enable;
    reg  stages$21$valid_in;
    reg  [33:0] stages$21$p_in;
    reg  [24:0] stages$21$x_in;
    reg  [33:0] stages$21$d_in;
    reg  stages$21$neg_in;
    wire  stages$21$valid;
    wire  [33:0] stages$21$p;
    wire  [24:0] stages$21$x;
    wire  [33:0] stages$21$d;
    wire  stages$21$neg;
    reg  stages$22$clock;
    reg  stages$22$enable;
    reg  stages$22$valid_in;
    reg  [33:0] stages$22$p_in;
    reg  [24:0] stages$22$x_in;
    reg  [33:0] stages$22$d_in;
    reg  stages$22$neg_in;
    wire  stages$22$valid;
    wire  [33:0] stages$22$p;
    wire  [24:0] stages$22$x;
    wire  [33:0] stages$22$d;
    wire  stages$22$neg;
    reg  stages$23$clock;
    reg  stages$23$enable;
    reg  stages$23$valid_in;
    reg  [33:0] stages$23$p_in;
    reg  [24:0] stages$23$x_in;
    reg  [33:0] stages$23$d_in;
    reg  stages$23$neg_in;
    wire  stages$23$valid;
    wire  [33:0] stages$23$p;
    wire  [24:0] stages$23$x;
    wire  [33:0] stages$23$d;
    wire  stages$23$neg;
    reg  stages$24$clock;
    reg  stages$24$enable;
    reg  stages$24$valid_in;
    reg  [33:0] stages$24$p_in;
    reg  [24:0] stages$24$x_in;
    reg  [33:0] stages$24$d_in;
    reg  stages$24$neg_in;
    wire  stages$24$valid;
    wire  [33:0] stages$24$p;
    wire  [24:0] stages$24$x;
    wire  [33:0] stages$24$d;
    wire  stages$24$neg;
    
    // Local signals
    reg  advance;
    reg  [57:0] m;
    reg  [24:0] last_x;
    
    // Sub module instances
    vector$lanes$0$div$stages$0 stages$0(
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
    vector$lanes$0$div$stages$1 stages$1(
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
    vector$lanes$0$div$stages$2 stages$2(
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
    vector$lanes$0$div$stages$3 stages$3(
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
    vector$lanes$0$div$stages$4 stages$4(
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
    vector$lanes$0$div$stages$5 stages$5(
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
    vector$lanes$0$div$stages$6 stages$6(
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
    vector$lanes$0$div$stages$7 stages$7(
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
    vector$lanes$0$div$stages$8 stages$8(
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
    vector$lanes$0$div$stages$9 stages$9(
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
    vector$lanes$0$div$stages$10 stages$10(
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
    vector$lanes$0$div$stages$11 stages$11(
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
    vector$lanes$0$div$stages$12 stages$12(
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
    vector$lanes$0$div$stages$13 stages$13(
        .clock(stages$13$clock),
        .enable(stages$13$enable),
        .valid_in(stages$13$valid_in),
        .p_in(stages$13$p_in),
        .x_in(stages$13$x_in),
        .d_in(stages$13$d_in),
        .neg_in(stages$13$neg_in),
        .valid(stages$13$valid),
        .p(stages$13$p),
        .x(stages$13$x),
        .d(stages$13$d),
        .neg(stages$13$neg)
    );
    vector$lanes$0$div$stages$14 stages$14(
        .clock(stages$14$clock),
        .enable(stages$14$enable),
        .valid_in(stages$14$valid_in),
        .p_in(stages$14$p_in),
        .x_in(stages$14$x_in),
        .d_in(stages$14$d_in),
        .neg_in(stages$14$neg_in),
        .valid(stages$14$valid),
        .p(stages$14$p),
        .x(stages$14$x),
        .d(stages$14$d),
        .neg(stages$14$neg)
    );
    vector$lanes$0$div$stages$15 stages$15(
        .clock(stages$15$clock),
        .enable(stages$15$enable),
        .valid_in(stages$15$valid_in),
        .p_in(stages$15$p_in),
        .x_in(stages$15$x_in),
        .d_in(stages$15$d_in),
        .neg_in(stages$15$neg_in),
        .valid(stages$15$valid),
        .p(stages$15$p),
        .x(stages$15$x),
        .d(stages$15$d),
        .neg(stages$15$neg)
    );
    vector$lanes$0$div$stages$16 stages$16(
        .clock(stages$16$clock),
        .enable(stages$16$enable),
        .valid_in(stages$16$valid_in),
        .p_in(stages$16$p_in),
        .x_in(stages$16$x_in),
        .d_in(stages$16$d_in),
        .neg_in(stages$16$neg_in),
        .valid(stages$16$valid),
        .p(stages$16$p),
        .x(stages$16$x),
        .d(stages$16$d),
        .neg(stages$16$neg)
    );
    vector$lanes$0$div$stages$17 stages$17(
        .clock(stages$17$clock),
        .enable(stages$17$enable),
        .valid_in(stages$17$valid_in),
        .p_in(stages$17$p_in),
        .x_in(stages$17$x_in),
        .d_in(stages$17$d_in),
        .neg_in(stages$17$neg_in),
        .valid(stages$17$valid),
        .p(stages$17$p),
        .x(stages$17$x),
        .d(stages$17$d),
        .neg(stages$17$neg)
    );
    vector$lanes$0$div$stages$18 stages$18(
        .clock(stages$18$clock),
        .enable(stages$18$enable),
        .valid_in(stages$18$valid_in),
        .p_in(stages$18$p_in),
        .x_in(stages$18$x_in),
        .d_in(stages$18$d_in),
        .neg_in(stages$18$neg_in),
        .valid(stages$18$valid),
        .p(stages$18$p),
        .x(stages$18$x),
        .d(stages$18$d),
        .neg(stages$18$neg)
    );
    vector$lanes$0$div$stages$19 stages$19(
        .clock(stages$19$clock),
        .enable(stages$19$enable),
        .valid_in(stages$19$valid_in),
        .p_in(stages$19$p_in),
        .x_in(stages$19$x_in),
        .d_in(stages$19$d_in),
        .neg_in(stages$19$neg_in),
        .valid(stages$19$valid),
        .p(stages$19$p),
        .x(stages$19$x),
        .d(stages$19$d),
        .neg(stages$19$neg)
    );
    vector$lanes$0$div$stages$20 stages$20(
        .clock(stages$20$clock),
        .enable(stages$20$enable),
        .valid_in(stages$20$valid_in),
        .p_in(stages$20$p_in),
        .x_in(stages$20$x_in),
        .d_in(stages$20$d_in),
        .neg_in(stages$20$neg_in),
        .valid(stages$20$valid),
        .p(stages$20$p),
        .x(stages$20$x),
        .d(stages$20$d),
        .neg(stages$20$neg)
    );
    vector$lanes$0$div$stages$21 stages$21(
        .clock(stages$21$clock),
        .enable(stages$21$enable),
        .valid_in(stages$21$valid_in),
        .p_in(stages$21$p_in),
        .x_in(stages$21$x_in),
        .d_in(stages$21$d_in),
        .neg_in(stages$21$neg_in),
        .valid(stages$21$valid),
        .p(stages$21$p),
        .x(stages$21$x),
        .d(stages$21$d),
        .neg(stages$21$neg)
    );
    vector$lanes$0$div$stages$22 stages$22(
        .clock(stages$22$clock),
        .enable(stages$22$enable),
        .valid_in(stages$22$valid_in),
        .p_in(stages$22$p_in),
        .x_in(stages$22$x_in),
        .d_in(stages$22$d_in),
        .neg_in(stages$22$neg_in),
        .valid(stages$22$valid),
        .p(stages$22$p),
        .x(stages$22$x),
        .d(stages$22$d),
        .neg(stages$22$neg)
    );
    vector$lanes$0$div$stages$23 stages$23(
        .clock(stages$23$clock),
        .enable(stages$23$enable),
        .valid_in(stages$23$valid_in),
        .p_in(stages$23$p_in),
        .x_in(stages$23$x_in),
        .d_in(stages$23$d_in),
        .neg_in(stages$23$neg_in),
        .valid(stages$23$valid),
        .p(stages$23$p),
        .x(stages$23$x),
        .d(stages$23$d),
        .neg(stages$23$neg)
    );
    vector$lanes$0$div$stages$24 stages$24(
        .clock(stages$24$clock),
        .enable(stages$24$enable),
        .valid_in(stages$24$valid_in),
        .p_in(stages$24$p_in),
        .x_in(stages$24$x_in),
        .d_in(stages$24$d_in),
        .neg_in(stages$24$neg_in),
        .valid(stages$24$valid),
        .p(stages$24$p),
        .x(stages$24$x),
        .d(stages$24$d),
        .neg(stages$24$neg)
    );
    
    // Update code
    always @(*) begin
        advance = ~hold & (~stages$24$valid | out_ready);
        out_valid = stages$24$valid;
        last_x = stages$24$x;
        out_r = stages$24$p;
        out_q = ((last_x) & 26'h3ffffff);
        if (stages$24$neg) begin
            out_q = ((last_x) & 26'h3ffffff) | q_sign;
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
        stages$13$clock = clock;
        stages$13$enable = advance;
        stages$14$clock = clock;
        stages$14$enable = advance;
        stages$15$clock = clock;
        stages$15$enable = advance;
        stages$16$clock = clock;
        stages$16$enable = advance;
        stages$17$clock = clock;
        stages$17$enable = advance;
        stages$18$clock = clock;
        stages$18$enable = advance;
        stages$19$clock = clock;
        stages$19$enable = advance;
        stages$20$clock = clock;
        stages$20$enable = advance;
        stages$21$clock = clock;
        stages$21$enable = advance;
        stages$22$clock = clock;
        stages$22$enable = advance;
        stages$23$clock = clock;
        stages$23$enable = advance;
        stages$24$clock = clock;
        stages$24$enable = advance;
        inp_ready = advance;
        m = inp_n;
        if (inp_n[n_msb]) begin
            m = ~inp_n;
        end
        stages$0$valid_in = inp_valid;
        stages$0$p_in = ((m >> qm) & 34'h3ffffffff);
        stages$0$x_in = m[(32'h0)+:(25)];
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
        stages$13$valid_in = stages$12$valid;
        stages$13$p_in = stages$12$p;
        stages$13$x_in = stages$12$x;
        stages$13$d_in = stages$12$d;
        stages$13$neg_in = stages$12$neg;
        stages$14$valid_in = stages$13$valid;
        stages$14$p_in = stages$13$p;
        stages$14$x_in = stages$13$x;
        stages$14$d_in = stages$13$d;
        stages$14$neg_in = stages$13$neg;
        stages$15$valid_in = stages$14$valid;
        stages$15$p_in = stages$14$p;
        stages$15$x_in = stages$14$x;
        stages$15$d_in = stages$14$d;
        stages$15$neg_in = stages$14$neg;
        stages$16$valid_in = stages$15$valid;
        stages$16$p_in = stages$15$p;
        stages$16$x_in = stages$15$x;
        stages$16$d_in = stages$15$d;
        stages$16$neg_in = stages$15$neg;
        stages$17$valid_in = stages$16$valid;
        stages$17$p_in = stages$16$p;
        stages$17$x_in = stages$16$x;
        stages$17$d_in = stages$16$d;
        stages$17$neg_in = stages$16$neg;
        stages$18$valid_in = stages$17$valid;
        stages$18$p_in = stages$17$p;
        stages$18$x_in = stages$17$x;
        stages$18$d_in = stages$17$d;
        stages$18$neg_in = stages$17$neg;
        stages$19$valid_in = stages$18$valid;
        stages$19$p_in = stages$18$p;
        stages$19$x_in = stages$18$x;
        stages$19$d_in = stages$18$d;
        stages$19$neg_in = stages$18$neg;
        stages$20$valid_in = stages$19$valid;
        stages$20$p_in = stages$19$p;
        stages$20$x_in = stages$19$x;
        stages$20$d_in = stages$19$d;
        stages$20$neg_in = stages$19$neg;
        stages$21$valid_in = stages$20$valid;
        stages$21$p_in = stages$20$p;
        stages$21$x_in = stages$20$x;
        stages$21$d_in = stages$20$d;
        stages$21$neg_in = stages$20$neg;
        stages$22$valid_in = stages$21$valid;
        stages$22$p_in = stages$21$p;
        stages$22$x_in = stages$21$x;
        stages$22$d_in = stages$21$d;
        stages$22$neg_in = stages$21$neg;
        stages$23$valid_in = stages$22$valid;
        stages$23$p_in = stages$22$p;
        stages$23$x_in = stages$22$x;
        stages$23$d_in = stages$22$d;
        stages$23$neg_in = stages$22$neg;
        stages$24$valid_in = stages$23$valid;
        stages$24$p_in = stages$23$p;
        stages$24$x_in = stages$23$x;
        stages$24$d_in = stages$23$d;
        stages$24$neg_in = stages$23$neg;
    end
    
endmodule // vector$lanes$0$div


module vector$lanes$0$div$stages$0(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    vector$lanes$0$div$stages$0$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    vector$lanes$0$div$stages$0$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$lanes$0$div$stages$0$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    vector$lanes$0$div$stages$0$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    vector$lanes$0$div$stages$0$neg_r neg_r(
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
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
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
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
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
    
endmodule // vector$lanes$0$div$stages$0


module vector$lanes$0$div$stages$0$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$0$d_r


module vector$lanes$0$div$stages$0$neg_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$0$neg_r


module vector$lanes$0$div$stages$0$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$0$p_r


module vector$lanes$0$div$stages$0$valid_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$0$valid_r


module vector$lanes$0$div$stages$0$x_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$0$x_r


module vector$lanes$0$div$stages$1(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    vector$lanes$0$div$stages$1$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    vector$lanes$0$div$stages$1$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$lanes$0$div$stages$1$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    vector$lanes$0$div$stages$1$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    vector$lanes$0$div$stages$1$neg_r neg_r(
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
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
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
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
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
    
endmodule // vector$lanes$0$div$stages$1


module vector$lanes$0$div$stages$1$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$1$d_r


module vector$lanes$0$div$stages$1$neg_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$1$neg_r


module vector$lanes$0$div$stages$1$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$1$p_r


module vector$lanes$0$div$stages$1$valid_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$1$valid_r


module vector$lanes$0$div$stages$1$x_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$1$x_r


module vector$lanes$0$div$stages$10(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    vector$lanes$0$div$stages$10$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    vector$lanes$0$div$stages$10$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$lanes$0$div$stages$10$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    vector$lanes$0$div$stages$10$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    vector$lanes$0$div$stages$10$neg_r neg_r(
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
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
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
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
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
    
endmodule // vector$lanes$0$div$stages$10


module vector$lanes$0$div$stages$10$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$10$d_r


module vector$lanes$0$div$stages$10$neg_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$10$neg_r


module vector$lanes$0$div$stages$10$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$10$p_r


module vector$lanes$0$div$stages$10$valid_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$10$valid_r


module vector$lanes$0$div$stages$10$x_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$10$x_r


module vector$lanes$0$div$stages$11(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    vector$lanes$0$div$stages$11$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    vector$lanes$0$div$stages$11$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$lanes$0$div$stages$11$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    vector$lanes$0$div$stages$11$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    vector$lanes$0$div$stages$11$neg_r neg_r(
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
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
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
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
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
    
endmodule // vector$lanes$0$div$stages$11


module vector$lanes$0$div$stages$11$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$11$d_r


module vector$lanes$0$div$stages$11$neg_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$11$neg_r


module vector$lanes$0$div$stages$11$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$11$p_r


module vector$lanes$0$div$stages$11$valid_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$11$valid_r


module vector$lanes$0$div$stages$11$x_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$11$x_r


module vector$lanes$0$div$stages$12(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    vector$lanes$0$div$stages$12$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    vector$lanes$0$div$stages$12$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$lanes$0$div$stages$12$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    vector$lanes$0$div$stages$12$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    vector$lanes$0$div$stages$12$neg_r neg_r(
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
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
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
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
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
    
endmodule // vector$lanes$0$div$stages$12


module vector$lanes$0$div$stages$12$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$12$d_r


module vector$lanes$0$div$stages$12$neg_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$12$neg_r


module vector$lanes$0$div$stages$12$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$12$p_r


module vector$lanes$0$div$stages$12$valid_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$12$valid_r


module vector$lanes$0$div$stages$12$x_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$12$x_r


module vector$lanes$0$div$stages$13(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    vector$lanes$0$div$stages$13$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    vector$lanes$0$div$stages$13$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$lanes$0$div$stages$13$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    vector$lanes$0$div$stages$13$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    vector$lanes$0$div$stages$13$neg_r neg_r(
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
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
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
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
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
    
endmodule // vector$lanes$0$div$stages$13


module vector$lanes$0$div$stages$13$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$13$d_r


module vector$lanes$0$div$stages$13$neg_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$13$neg_r


module vector$lanes$0$div$stages$13$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$13$p_r


module vector$lanes$0$div$stages$13$valid_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$13$valid_r


module vector$lanes$0$div$stages$13$x_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$13$x_r


module vector$lanes$0$div$stages$14(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    vector$lanes$0$div$stages$14$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    vector$lanes$0$div$stages$14$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$lanes$0$div$stages$14$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    vector$lanes$0$div$stages$14$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    vector$lanes$0$div$stages$14$neg_r neg_r(
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
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
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
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
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
    
endmodule // vector$lanes$0$div$stages$14


module vector$lanes$0$div$stages$14$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$14$d_r


module vector$lanes$0$div$stages$14$neg_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$14$neg_r


module vector$lanes$0$div$stages$14$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$14$p_r


module vector$lanes$0$div$stages$14$valid_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$14$valid_r


module vector$lanes$0$div$stages$14$x_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$14$x_r


module vector$lanes$0$div$stages$15(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    vector$lanes$0$div$stages$15$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    vector$lanes$0$div$stages$15$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$lanes$0$div$stages$15$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    vector$lanes$0$div$stages$15$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    vector$lanes$0$div$stages$15$neg_r neg_r(
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
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
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
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
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
    
endmodule // vector$lanes$0$div$stages$15


module vector$lanes$0$div$stages$15$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$15$d_r


module vector$lanes$0$div$stages$15$neg_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$15$neg_r


module vector$lanes$0$div$stages$15$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$15$p_r


module vector$lanes$0$div$stages$15$valid_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$15$valid_r


module vector$lanes$0$div$stages$15$x_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$15$x_r


module vector$lanes$0$div$stages$16(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    vector$lanes$0$div$stages$16$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    vector$lanes$0$div$stages$16$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$lanes$0$div$stages$16$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    vector$lanes$0$div$stages$16$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    vector$lanes$0$div$stages$16$neg_r neg_r(
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
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
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
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
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
    
endmodule // vector$lanes$0$div$stages$16


module vector$lanes$0$div$stages$16$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$16$d_r


module vector$lanes$0$div$stages$16$neg_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$16$neg_r


module vector$lanes$0$div$stages$16$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$16$p_r


module vector$lanes$0$div$stages$16$valid_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$16$valid_r


module vector$lanes$0$div$stages$16$x_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$16$x_r


module vector$lanes$0$div$stages$17(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    vector$lanes$0$div$stages$17$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    vector$lanes$0$div$stages$17$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$lanes$0$div$stages$17$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    vector$lanes$0$div$stages$17$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    vector$lanes$0$div$stages$17$neg_r neg_r(
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
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
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
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
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
    
endmodule // vector$lanes$0$div$stages$17


module vector$lanes$0$div$stages$17$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$17$d_r


module vector$lanes$0$div$stages$17$neg_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$17$neg_r


module vector$lanes$0$div$stages$17$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$17$p_r


module vector$lanes$0$div$stages$17$valid_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$17$valid_r


module vector$lanes$0$div$stages$17$x_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$17$x_r


module vector$lanes$0$div$stages$18(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    vector$lanes$0$div$stages$18$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    vector$lanes$0$div$stages$18$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$lanes$0$div$stages$18$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    vector$lanes$0$div$stages$18$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    vector$lanes$0$div$stages$18$neg_r neg_r(
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
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
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
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
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
    
endmodule // vector$lanes$0$div$stages$18


module vector$lanes$0$div$stages$18$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$18$d_r


module vector$lanes$0$div$stages$18$neg_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$18$neg_r


module vector$lanes$0$div$stages$18$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$18$p_r


module vector$lanes$0$div$stages$18$valid_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$18$valid_r


module vector$lanes$0$div$stages$18$x_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$18$x_r


module vector$lanes$0$div$stages$19(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    vector$lanes$0$div$stages$19$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    vector$lanes$0$div$stages$19$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$lanes$0$div$stages$19$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    vector$lanes$0$div$stages$19$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    vector$lanes$0$div$stages$19$neg_r neg_r(
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
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
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
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
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
    
endmodule // vector$lanes$0$div$stages$19


module vector$lanes$0$div$stages$19$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$19$d_r


module vector$lanes$0$div$stages$19$neg_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$19$neg_r


module vector$lanes$0$div$stages$19$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$19$p_r


module vector$lanes$0$div$stages$19$valid_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$19$valid_r


module vector$lanes$0$div$stages$19$x_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$19$x_r


module vector$lanes$0$div$stages$2(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    vector$lanes$0$div$stages$2$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    vector$lanes$0$div$stages$2$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$lanes$0$div$stages$2$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    vector$lanes$0$div$stages$2$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    vector$lanes$0$div$stages$2$neg_r neg_r(
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
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
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
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
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
    
endmodule // vector$lanes$0$div$stages$2


module vector$lanes$0$div$stages$2$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$2$d_r


module vector$lanes$0$div$stages$2$neg_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$2$neg_r


module vector$lanes$0$div$stages$2$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$2$p_r


module vector$lanes$0$div$stages$2$valid_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$2$valid_r


module vector$lanes$0$div$stages$2$x_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$2$x_r


module vector$lanes$0$div$stages$20(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    vector$lanes$0$div$stages$20$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    vector$lanes$0$div$stages$20$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$lanes$0$div$stages$20$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    vector$lanes$0$div$stages$20$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    vector$lanes$0$div$stages$20$neg_r neg_r(
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
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
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
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
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
    
endmodule // vector$lanes$0$div$stages$20


module vector$lanes$0$div$stages$20$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$20$d_r


module vector$lanes$0$div$stages$20$neg_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$20$neg_r


module vector$lanes$0$div$stages$20$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$20$p_r


module vector$lanes$0$div$stages$20$valid_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$20$valid_r


module vector$lanes$0$div$stages$20$x_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$20$x_r


module vector$lanes$0$div$stages$21(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    vector$lanes$0$div$stages$21$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    vector$lanes$0$div$stages$21$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$lanes$0$div$stages$21$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    vector$lanes$0$div$stages$21$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    vector$lanes$0$div$stages$21$neg_r neg_r(
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
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
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
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
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
    
endmodule // vector$lanes$0$div$stages$21


module vector$lanes$0$div$stages$21$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$21$d_r


module vector$lanes$0$div$stages$21$neg_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$21$neg_r


module vector$lanes$0$div$stages$21$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$21$p_r


module vector$lanes$0$div$stages$21$valid_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$21$valid_r


module vector$lanes$0$div$stages$21$x_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$21$x_r


module vector$lanes$0$div$stages$22(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    vector$lanes$0$div$stages$22$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    vector$lanes$0$div$stages$22$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$lanes$0$div$stages$22$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    vector$lanes$0$div$stages$22$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    vector$lanes$0$div$stages$22$neg_r neg_r(
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
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
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
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
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
    
endmodule // vector$lanes$0$div$stages$22


module vector$lanes$0$div$stages$22$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$22$d_r


module vector$lanes$0$div$stages$22$neg_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$22$neg_r


module vector$lanes$0$div$stages$22$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$22$p_r


module vector$lanes$0$div$stages$22$valid_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$22$valid_r


module vector$lanes$0$div$stages$22$x_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$22$x_r


module vector$lanes$0$div$stages$23(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    vector$lanes$0$div$stages$23$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    vector$lanes$0$div$stages$23$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$lanes$0$div$stages$23$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    vector$lanes$0$div$stages$23$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    vector$lanes$0$div$stages$23$neg_r neg_r(
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
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
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
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
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
    
endmodule // vector$lanes$0$div$stages$23


module vector$lanes$0$div$stages$23$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$23$d_r


module vector$lanes$0$div$stages$23$neg_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$23$neg_r


module vector$lanes$0$div$stages$23$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$23$p_r


module vector$lanes$0$div$stages$23$valid_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$23$valid_r


module vector$lanes$0$div$stages$23$x_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$23$x_r


module vector$lanes$0$div$stages$24(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b1;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    vector$lanes$0$div$stages$24$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    vector$lanes$0$div$stages$24$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$lanes$0$div$stages$24$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    vector$lanes$0$div$stages$24$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    vector$lanes$0$div$stages$24$neg_r neg_r(
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
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
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
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
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
    
endmodule // vector$lanes$0$div$stages$24


module vector$lanes$0$div$stages$24$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$24$d_r


module vector$lanes$0$div$stages$24$neg_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$24$neg_r


module vector$lanes$0$div$stages$24$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$24$p_r


module vector$lanes$0$div$stages$24$valid_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$24$valid_r


module vector$lanes$0$div$stages$24$x_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$24$x_r


module vector$lanes$0$div$stages$3(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    vector$lanes$0$div$stages$3$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    vector$lanes$0$div$stages$3$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$lanes$0$div$stages$3$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    vector$lanes$0$div$stages$3$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    vector$lanes$0$div$stages$3$neg_r neg_r(
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
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
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
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
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
    
endmodule // vector$lanes$0$div$stages$3


module vector$lanes$0$div$stages$3$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$3$d_r


module vector$lanes$0$div$stages$3$neg_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$3$neg_r


module vector$lanes$0$div$stages$3$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$3$p_r


module vector$lanes$0$div$stages$3$valid_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$3$valid_r


module vector$lanes$0$div$stages$3$x_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$3$x_r


module vector$lanes$0$div$stages$4(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    vector$lanes$0$div$stages$4$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    vector$lanes$0$div$stages$4$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$lanes$0$div$stages$4$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    vector$lanes$0$div$stages$4$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    vector$lanes$0$div$stages$4$neg_r neg_r(
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
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
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
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
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
    
endmodule // vector$lanes$0$div$stages$4


module vector$lanes$0$div$stages$4$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$4$d_r


module vector$lanes$0$div$stages$4$neg_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$4$neg_r


module vector$lanes$0$div$stages$4$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$4$p_r


module vector$lanes$0$div$stages$4$valid_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$4$valid_r


module vector$lanes$0$div$stages$4$x_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$4$x_r


module vector$lanes$0$div$stages$5(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    vector$lanes$0$div$stages$5$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    vector$lanes$0$div$stages$5$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$lanes$0$div$stages$5$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    vector$lanes$0$div$stages$5$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    vector$lanes$0$div$stages$5$neg_r neg_r(
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
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
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
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
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
    
endmodule // vector$lanes$0$div$stages$5


module vector$lanes$0$div$stages$5$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$5$d_r


module vector$lanes$0$div$stages$5$neg_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$5$neg_r


module vector$lanes$0$div$stages$5$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$5$p_r


module vector$lanes$0$div$stages$5$valid_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$5$valid_r


module vector$lanes$0$div$stages$5$x_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$5$x_r


module vector$lanes$0$div$stages$6(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    vector$lanes$0$div$stages$6$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    vector$lanes$0$div$stages$6$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$lanes$0$div$stages$6$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    vector$lanes$0$div$stages$6$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    vector$lanes$0$div$stages$6$neg_r neg_r(
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
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
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
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
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
    
endmodule // vector$lanes$0$div$stages$6


module vector$lanes$0$div$stages$6$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$6$d_r


module vector$lanes$0$div$stages$6$neg_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$6$neg_r


module vector$lanes$0$div$stages$6$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$6$p_r


module vector$lanes$0$div$stages$6$valid_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$6$valid_r


module vector$lanes$0$div$stages$6$x_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$6$x_r


module vector$lanes$0$div$stages$7(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    vector$lanes$0$div$stages$7$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    vector$lanes$0$div$stages$7$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$lanes$0$div$stages$7$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    vector$lanes$0$div$stages$7$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    vector$lanes$0$div$stages$7$neg_r neg_r(
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
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
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
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
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
    
endmodule // vector$lanes$0$div$stages$7


module vector$lanes$0$div$stages$7$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$7$d_r


module vector$lanes$0$div$stages$7$neg_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$7$neg_r


module vector$lanes$0$div$stages$7$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$7$p_r


module vector$lanes$0$div$stages$7$valid_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$7$valid_r


module vector$lanes$0$div$stages$7$x_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$7$x_r


module vector$lanes$0$div$stages$8(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    vector$lanes$0$div$stages$8$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    vector$lanes$0$div$stages$8$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$lanes$0$div$stages$8$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    vector$lanes$0$div$stages$8$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    vector$lanes$0$div$stages$8$neg_r neg_r(
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
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
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
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
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
    
endmodule // vector$lanes$0$div$stages$8


module vector$lanes$0$div$stages$8$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$8$d_r


module vector$lanes$0$div$stages$8$neg_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$8$neg_r


module vector$lanes$0$div$stages$8$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$8$p_r


module vector$lanes$0$div$stages$8$valid_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$8$valid_r


module vector$lanes$0$div$stages$8$x_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$8$x_r


module vector$lanes$0$div$stages$9(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    vector$lanes$0$div$stages$9$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    vector$lanes$0$div$stages$9$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$lanes$0$div$stages$9$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    vector$lanes$0$div$stages$9$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    vector$lanes$0$div$stages$9$neg_r neg_r(
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
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
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
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
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
    
endmodule // vector$lanes$0$div$stages$9


module vector$lanes$0$div$stages$9$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$9$d_r


module vector$lanes$0$div$stages$9$neg_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$9$neg_r


module vector$lanes$0$div$stages$9$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div$stages$9$p_r


module vector$lanes$0$div$stages$9$valid_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$9$valid_r


module vector$lanes$0$div$stages$9$x_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$div$stages$9$x_r


module vector$lanes$0$div_d(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$div_d


module vector$lanes$0$dtag_dl(clock,en,d,q);
    
    // Module arguments
    input wire  clock;
    input wire  en;
    input wire  [16:0] d;
    output reg  [16:0] q;
    
    // Stub signals
    reg  [16:0] stages$0$d;
    wire  [16:0] stages$0$q;
    reg  stages$0$clock;
    reg  [16:0] stages$1$d;
    wire  [16:0] stages$1$q;
    reg  stages$1$clock;
    reg  [16:0] stages$2$d;
    wire  [16:0] stages$2$q;
    reg  stages$2$clock;
    reg  [16:0] stages$3$d;
    wire  [16:0] stages$3$q;
    reg  stages$3$clock;
    reg  [16:0] stages$4$d;
    wire  [16:0] stages$4$q;
    reg  stages$4$clock;
    reg  [16:0] stages$5$d;
    wire  [16:0] stages$5$q;
    reg  stages$5$clock;
    reg  [16:0] stages$6$d;
    wire  [16:0] stages$6$q;
    reg  stages$6$clock;
    reg  [16:0] stages$7$d;
    wire  [16:0] stages$7$q;
    reg  stages$7$clock;
    reg  [16:0] stages$8$d;
    wire  [16:0] stages$8$q;
    reg  stages$8$clock;
    reg  [16:0] stages$9$d;
    wire  [16:0] stages$9$q;
    reg  stages$9$clock;
    reg  [16:0] stages$10$d;
    wire  [16:0] stages$10$q;
    reg  stages$10$clock;
    reg  [16:0] stages$11$d;
    wire  [16:0] stages$11$q;
    reg  stages$11$clock;
    reg  [16:0] stages$12$d;
    wire  [16:0] stages$12$q;
    reg  stages$12$clock;
    reg  [16:0] stages$13$d;
    wire  [16:0] stages$13$q;
    reg  stages$13$clock;
    reg  [16:0] stages$14$d;
    wire  [16:0] stages$14$q;
    reg  stages$14$clock;
    reg  [16:0] stages$15$d;
    wire  [16:0] stages$15$q;
    reg  stages$15$clock;
    reg  [16:0] stages$16$d;
    wire  [16:0] stages$16$q;
    reg  stages$16$clock;
    reg  [16:0] stages$17$d;
    wire  [16:0] stages$17$q;
    reg  stages$17$clock;
    reg  [16:0] stages$18$d;
    wire  [16:0] stages$18$q;
    reg  stages$18$clock;
    reg  [16:0] stages$19$d;
    wire  [16:0] stages$19$q;
    reg  stages$19$clock;
    reg  [16:0] stages$20$d;
    wire  [16:0] stages$20$q;
    reg  stages$20$clock;
    reg  [16:0] stages$21$d;
    wire  [16:0] stages$21$q;
    reg  stages$21$clock;
    reg  [16:0] stages$22$d;
    wire  [16:0] stages$22$q;
    reg  stages$22$clock;
    reg  [16:0] stages$23$d;
    wire  [16:0] stages$23$q;
    reg  stages$23$clock;
    reg  [16:0] stages$24$d;
    wire  [16:0] stages$24$q;
    reg  stages$24$clock;
    reg  [16:0] stages$25$d;
    wire  [16:0] stages$25$q;
    reg  stages$25$clock;
    reg  [16:0] stages$26$d;
    wire  [16:0] stages$26$q;
    reg  stages$26$clock;
    reg  [16:0] stages$27$d;
    wire  [16:0] stages$27$q;
    reg  stages$27$clock;
    reg  [16:0] stages$28$d;
    wire  [16:0] stages$28$q;
    reg  stages$28$clock;
    reg  [16:0] stages$29$d;
    wire  [16:0] stages$29$q;
    reg  stages$29$clock;
    reg  [16:0] stages$30$d;
    wire  [16:0] stages$30$q;
    reg  stages$30$clock;
    reg  [16:0] stages$31$d;
    wire  [16:0] stages$31$q;
    reg  stages$31$clock;
    reg  [16:0] stages$32$d;
    wire  [16:0] stages$32$q;
    reg  stages$32$clock;
    reg  [16:0] stages$33$d;
    wire  [16:0] stages$33$q;
    reg  stages$33$clock;
    
    // Sub module instances
    vector$lanes$0$dtag_dl$stages$0 stages$0(
        .d(stages$0$d),
        .q(stages$0$q),
        .clock(stages$0$clock)
    );
    vector$lanes$0$dtag_dl$stages$1 stages$1(
        .d(stages$1$d),
        .q(stages$1$q),
        .clock(stages$1$clock)
    );
    vector$lanes$0$dtag_dl$stages$2 stages$2(
        .d(stages$2$d),
        .q(stages$2$q),
        .clock(stages$2$clock)
    );
    vector$lanes$0$dtag_dl$stages$3 stages$3(
        .d(stages$3$d),
        .q(stages$3$q),
        .clock(stages$3$clock)
    );
    vector$lanes$0$dtag_dl$stages$4 stages$4(
        .d(stages$4$d),
        .q(stages$4$q),
        .clock(stages$4$clock)
    );
    vector$lanes$0$dtag_dl$stages$5 stages$5(
        .d(stages$5$d),
        .q(stages$5$q),
        .clock(stages$5$clock)
    );
    vector$lanes$0$dtag_dl$stages$6 stages$6(
        .d(stages$6$d),
        .q(stages$6$q),
        .clock(stages$6$clock)
    );
    vector$lanes$0$dtag_dl$stages$7 stages$7(
        .d(stages$7$d),
        .q(stages$7$q),
        .clock(stages$7$clock)
    );
    vector$lanes$0$dtag_dl$stages$8 stages$8(
        .d(stages$8$d),
        .q(stages$8$q),
        .clock(stages$8$clock)
    );
    vector$lanes$0$dtag_dl$stages$9 stages$9(
        .d(stages$9$d),
        .q(stages$9$q),
        .clock(stages$9$clock)
    );
    vector$lanes$0$dtag_dl$stages$10 stages$10(
        .d(stages$10$d),
        .q(stages$10$q),
        .clock(stages$10$clock)
    );
    vector$lanes$0$dtag_dl$stages$11 stages$11(
        .d(stages$11$d),
        .q(stages$11$q),
        .clock(stages$11$clock)
    );
    vector$lanes$0$dtag_dl$stages$12 stages$12(
        .d(stages$12$d),
        .q(stages$12$q),
        .clock(stages$12$clock)
    );
    vector$lanes$0$dtag_dl$stages$13 stages$13(
        .d(stages$13$d),
        .q(stages$13$q),
        .clock(stages$13$clock)
    );
    vector$lanes$0$dtag_dl$stages$14 stages$14(
        .d(stages$14$d),
        .q(stages$14$q),
        .clock(stages$14$clock)
    );
    vector$lanes$0$dtag_dl$stages$15 stages$15(
        .d(stages$15$d),
        .q(stages$15$q),
        .clock(stages$15$clock)
    );
    vector$lanes$0$dtag_dl$stages$16 stages$16(
        .d(stages$16$d),
        .q(stages$16$q),
        .clock(stages$16$clock)
    );
    vector$lanes$0$dtag_dl$stages$17 stages$17(
        .d(stages$17$d),
        .q(stages$17$q),
        .clock(stages$17$clock)
    );
    vector$lanes$0$dtag_dl$stages$18 stages$18(
        .d(stages$18$d),
        .q(stages$18$q),
        .clock(stages$18$clock)
    );
    vector$lanes$0$dtag_dl$stages$19 stages$19(
        .d(stages$19$d),
        .q(stages$19$q),
        .clock(stages$19$clock)
    );
    vector$lanes$0$dtag_dl$stages$20 stages$20(
        .d(stages$20$d),
        .q(stages$20$q),
        .clock(stages$20$clock)
    );
    vector$lanes$0$dtag_dl$stages$21 stages$21(
        .d(stages$21$d),
        .q(stages$21$q),
        .clock(stages$21$clock)
    );
    vector$lanes$0$dtag_dl$stages$22 stages$22(
        .d(stages$22$d),
        .q(stages$22$q),
        .clock(stages$22$clock)
    );
    vector$lanes$0$dtag_dl$stages$23 stages$23(
        .d(stages$23$d),
        .q(stages$23$q),
        .clock(stages$23$clock)
    );
    vector$lanes$0$dtag_dl$stages$24 stages$24(
        .d(stages$24$d),
        .q(stages$24$q),
        .clock(stages$24$clock)
    );
    vector$lanes$0$dtag_dl$stages$25 stages$25(
        .d(stages$25$d),
        .q(stages$25$q),
        .clock(stages$25$clock)
    );
    vector$lanes$0$dtag_dl$stages$26 stages$26(
        .d(stages$26$d),
        .q(stages$26$q),
        .clock(stages$26$clock)
    );
    vector$lanes$0$dtag_dl$stages$27 stages$27(
        .d(stages$27$d),
        .q(stages$27$q),
        .clock(stages$27$clock)
    );
    vector$lanes$0$dtag_dl$stages$28 stages$28(
        .d(stages$28$d),
        .q(stages$28$q),
        .clock(stages$28$clock)
    );
    vector$lanes$0$dtag_dl$stages$29 stages$29(
        .d(stages$29$d),
        .q(stages$29$q),
        .clock(stages$29$clock)
    );
    vector$lanes$0$dtag_dl$stages$30 stages$30(
        .d(stages$30$d),
        .q(stages$30$q),
        .clock(stages$30$clock)
    );
    vector$lanes$0$dtag_dl$stages$31 stages$31(
        .d(stages$31$d),
        .q(stages$31$q),
        .clock(stages$31$clock)
    );
    vector$lanes$0$dtag_dl$stages$32 stages$32(
        .d(stages$32$d),
        .q(stages$32$q),
        .clock(stages$32$clock)
    );
    vector$lanes$0$dtag_dl$stages$33 stages$33(
        .d(stages$33$d),
        .q(stages$33$q),
        .clock(stages$33$clock)
    );
    
    // Update code
    always @(*) begin
        stages$0$clock = clock;
        stages$0$d = stages$0$q;
        stages$1$clock = clock;
        stages$1$d = stages$1$q;
        stages$2$clock = clock;
        stages$2$d = stages$2$q;
        stages$3$clock = clock;
        stages$3$d = stages$3$q;
        stages$4$clock = clock;
        stages$4$d = stages$4$q;
        stages$5$clock = clock;
        stages$5$d = stages$5$q;
        stages$6$clock = clock;
        stages$6$d = stages$6$q;
        stages$7$clock = clock;
        stages$7$d = stages$7$q;
        stages$8$clock = clock;
        stages$8$d = stages$8$q;
        stages$9$clock = clock;
        stages$9$d = stages$9$q;
        stages$10$clock = clock;
        stages$10$d = stages$10$q;
        stages$11$clock = clock;
        stages$11$d = stages$11$q;
        stages$12$clock = clock;
        stages$12$d = stages$12$q;
        stages$13$clock = clock;
        stages$13$d = stages$13$q;
        stages$14$clock = clock;
        stages$14$d = stages$14$q;
        stages$15$clock = clock;
        stages$15$d = stages$15$q;
        stages$16$clock = clock;
        stages$16$d = stages$16$q;
        stages$17$clock = clock;
        stages$17$d = stages$17$q;
        stages$18$clock = clock;
        stages$18$d = stages$18$q;
        stages$19$clock = clock;
        stages$19$d = stages$19$q;
        stages$20$clock = clock;
        stages$20$d = stages$20$q;
        stages$21$clock = clock;
        stages$21$d = stages$21$q;
        stages$22$clock = clock;
        stages$22$d = stages$22$q;
        stages$23$clock = clock;
        stages$23$d = stages$23$q;
        stages$24$clock = clock;
        stages$24$d = stages$24$q;
        stages$25$clock = clock;
        stages$25$d = stages$25$q;
        stages$26$clock = clock;
        stages$26$d = stages$26$q;
        stages$27$clock = clock;
        stages$27$d = stages$27$q;
        stages$28$clock = clock;
        stages$28$d = stages$28$q;
        stages$29$clock = clock;
        stages$29$d = stages$29$q;
        stages$30$clock = clock;
        stages$30$d = stages$30$q;
        stages$31$clock = clock;
        stages$31$d = stages$31$q;
        stages$32$clock = clock;
        stages$32$d = stages$32$q;
        stages$33$clock = clock;
        stages$33$d = stages$33$q;
        if (en) begin
            stages$0$d = d;
            stages$1$d = stages$0$q;
            stages$2$d = stages$1$q;
            stages$3$d = stages$2$q;
            stages$4$d = stages$3$q;
            stages$5$d = stages$4$q;
            stages$6$d = stages$5$q;
            stages$7$d = stages$6$q;
            stages$8$d = stages$7$q;
            stages$9$d = stages$8$q;
            stages$10$d = stages$9$q;
            stages$11$d = stages$10$q;
            stages$12$d = stages$11$q;
            stages$13$d = stages$12$q;
            stages$14$d = stages$13$q;
            stages$15$d = stages$14$q;
            stages$16$d = stages$15$q;
            stages$17$d = stages$16$q;
            stages$18$d = stages$17$q;
            stages$19$d = stages$18$q;
            stages$20$d = stages$19$q;
            stages$21$d = stages$20$q;
            stages$22$d = stages$21$q;
            stages$23$d = stages$22$q;
            stages$24$d = stages$23$q;
            stages$25$d = stages$24$q;
            stages$26$d = stages$25$q;
            stages$27$d = stages$26$q;
            stages$28$d = stages$27$q;
            stages$29$d = stages$28$q;
            stages$30$d = stages$29$q;
            stages$31$d = stages$30$q;
            stages$32$d = stages$31$q;
            stages$33$d = stages$32$q;
        end
        q = stages$33$q;
    end
    
endmodule // vector$lanes$0$dtag_dl


module vector$lanes$0$dtag_dl$stages$0(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$dtag_dl$stages$0


module vector$lanes$0$dtag_dl$stages$1(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$dtag_dl$stages$1


module vector$lanes$0$dtag_dl$stages$10(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$dtag_dl$stages$10


module vector$lanes$0$dtag_dl$stages$11(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$dtag_dl$stages$11


module vector$lanes$0$dtag_dl$stages$12(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$dtag_dl$stages$12


module vector$lanes$0$dtag_dl$stages$13(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$dtag_dl$stages$13


module vector$lanes$0$dtag_dl$stages$14(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$dtag_dl$stages$14


module vector$lanes$0$dtag_dl$stages$15(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$dtag_dl$stages$15


module vector$lanes$0$dtag_dl$stages$16(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$dtag_dl$stages$16


module vector$lanes$0$dtag_dl$stages$17(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$dtag_dl$stages$17


module vector$lanes$0$dtag_dl$stages$18(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$dtag_dl$stages$18


module vector$lanes$0$dtag_dl$stages$19(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$dtag_dl$stages$19


module vector$lanes$0$dtag_dl$stages$2(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$dtag_dl$stages$2


module vector$lanes$0$dtag_dl$stages$20(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$dtag_dl$stages$20


module vector$lanes$0$dtag_dl$stages$21(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$dtag_dl$stages$21


module vector$lanes$0$dtag_dl$stages$22(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$dtag_dl$stages$22


module vector$lanes$0$dtag_dl$stages$23(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$dtag_dl$stages$23


module vector$lanes$0$dtag_dl$stages$24(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$dtag_dl$stages$24


module vector$lanes$0$dtag_dl$stages$25(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$dtag_dl$stages$25


module vector$lanes$0$dtag_dl$stages$26(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$dtag_dl$stages$26


module vector$lanes$0$dtag_dl$stages$27(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$dtag_dl$stages$27


module vector$lanes$0$dtag_dl$stages$28(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$dtag_dl$stages$28


module vector$lanes$0$dtag_dl$stages$29(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$dtag_dl$stages$29


module vector$lanes$0$dtag_dl$stages$3(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$dtag_dl$stages$3


module vector$lanes$0$dtag_dl$stages$30(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$dtag_dl$stages$30


module vector$lanes$0$dtag_dl$stages$31(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$dtag_dl$stages$31


module vector$lanes$0$dtag_dl$stages$32(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$dtag_dl$stages$32


module vector$lanes$0$dtag_dl$stages$33(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$dtag_dl$stages$33


module vector$lanes$0$dtag_dl$stages$4(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$dtag_dl$stages$4


module vector$lanes$0$dtag_dl$stages$5(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$dtag_dl$stages$5


module vector$lanes$0$dtag_dl$stages$6(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$dtag_dl$stages$6


module vector$lanes$0$dtag_dl$stages$7(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$dtag_dl$stages$7


module vector$lanes$0$dtag_dl$stages$8(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$dtag_dl$stages$8


module vector$lanes$0$dtag_dl$stages$9(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$dtag_dl$stages$9


module vector$lanes$0$eq$0(x,y);
    
    // Module arguments
    input wire  [27:0] x;
    output reg  [29:0] y;
    
    // Constant declarations
    localparam  msb = 8'h1b;
    localparam  ext = 30'h30000000;
    
    // Update code
    always @(*) begin
        y = ((x) & 30'h3fffffff);
        if (x[msb]) begin
            y = ((x) & 30'h3fffffff) | ext;
        end
    end
    
endmodule // vector$lanes$0$eq$0


module vector$lanes$0$eq$1(x,y);
    
    // Module arguments
    input wire  [27:0] x;
    output reg  [29:0] y;
    
    // Constant declarations
    localparam  msb = 8'h1b;
    localparam  ext = 30'h30000000;
    
    // Update code
    always @(*) begin
        y = ((x) & 30'h3fffffff);
        if (x[msb]) begin
            y = ((x) & 30'h3fffffff) | ext;
        end
    end
    
endmodule // vector$lanes$0$eq$1


module vector$lanes$0$eq$2(x,y);
    
    // Module arguments
    input wire  [27:0] x;
    output reg  [29:0] y;
    
    // Constant declarations
    localparam  msb = 8'h1b;
    localparam  ext = 30'h30000000;
    
    // Update code
    always @(*) begin
        y = ((x) & 30'h3fffffff);
        if (x[msb]) begin
            y = ((x) & 30'h3fffffff) | ext;
        end
    end
    
endmodule // vector$lanes$0$eq$2


module vector$lanes$0$exp8(d,q,clock);
    
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
          
endmodule // vector$lanes$0$exp8


module vector$lanes$0$exp_dl(clock,en,d,q);
    
    // Module arguments
    input wire  clock;
    input wire  en;
    input wire  [7:0] d;
    output reg  [7:0] q;
    
    // Stub signals
    reg  [7:0] stages$0$d;
    wire  [7:0] stages$0$q;
    reg  stages$0$clock;
    reg  [7:0] stages$1$d;
    wire  [7:0] stages$1$q;
    reg  stages$1$clock;
    reg  [7:0] stages$2$d;
    wire  [7:0] stages$2$q;
    reg  stages$2$clock;
    reg  [7:0] stages$3$d;
    wire  [7:0] stages$3$q;
    reg  stages$3$clock;
    reg  [7:0] stages$4$d;
    wire  [7:0] stages$4$q;
    reg  stages$4$clock;
    reg  [7:0] stages$5$d;
    wire  [7:0] stages$5$q;
    reg  stages$5$clock;
    reg  [7:0] stages$6$d;
    wire  [7:0] stages$6$q;
    reg  stages$6$clock;
    reg  [7:0] stages$7$d;
    wire  [7:0] stages$7$q;
    reg  stages$7$clock;
    reg  [7:0] stages$8$d;
    wire  [7:0] stages$8$q;
    reg  stages$8$clock;
    reg  [7:0] stages$9$d;
    wire  [7:0] stages$9$q;
    reg  stages$9$clock;
    reg  [7:0] stages$10$d;
    wire  [7:0] stages$10$q;
    reg  stages$10$clock;
    reg  [7:0] stages$11$d;
    wire  [7:0] stages$11$q;
    reg  stages$11$clock;
    reg  [7:0] stages$12$d;
    wire  [7:0] stages$12$q;
    reg  stages$12$clock;
    reg  [7:0] stages$13$d;
    wire  [7:0] stages$13$q;
    reg  stages$13$clock;
    reg  [7:0] stages$14$d;
    wire  [7:0] stages$14$q;
    reg  stages$14$clock;
    reg  [7:0] stages$15$d;
    wire  [7:0] stages$15$q;
    reg  stages$15$clock;
    reg  [7:0] stages$16$d;
    wire  [7:0] stages$16$q;
    reg  stages$16$clock;
    reg  [7:0] stages$17$d;
    wire  [7:0] stages$17$q;
    reg  stages$17$clock;
    reg  [7:0] stages$18$d;
    wire  [7:0] stages$18$q;
    reg  stages$18$clock;
    reg  [7:0] stages$19$d;
    wire  [7:0] stages$19$q;
    reg  stages$19$clock;
    reg  [7:0] stages$20$d;
    wire  [7:0] stages$20$q;
    reg  stages$20$clock;
    reg  [7:0] stages$21$d;
    wire  [7:0] stages$21$q;
    reg  stages$21$clock;
    reg  [7:0] stages$22$d;
    wire  [7:0] stages$22$q;
    reg  stages$22$clock;
    reg  [7:0] stages$23$d;
    wire  [7:0] stages$23$q;
    reg  stages$23$clock;
    reg  [7:0] stages$24$d;
    wire  [7:0] stages$24$q;
    reg  stages$24$clock;
    reg  [7:0] stages$25$d;
    wire  [7:0] stages$25$q;
    reg  stages$25$clock;
    reg  [7:0] stages$26$d;
    wire  [7:0] stages$26$q;
    reg  stages$26$clock;
    reg  [7:0] stages$27$d;
    wire  [7:0] stages$27$q;
    reg  stages$27$clock;
    
    // Sub module instances
    vector$lanes$0$exp_dl$stages$0 stages$0(
        .d(stages$0$d),
        .q(stages$0$q),
        .clock(stages$0$clock)
    );
    vector$lanes$0$exp_dl$stages$1 stages$1(
        .d(stages$1$d),
        .q(stages$1$q),
        .clock(stages$1$clock)
    );
    vector$lanes$0$exp_dl$stages$2 stages$2(
        .d(stages$2$d),
        .q(stages$2$q),
        .clock(stages$2$clock)
    );
    vector$lanes$0$exp_dl$stages$3 stages$3(
        .d(stages$3$d),
        .q(stages$3$q),
        .clock(stages$3$clock)
    );
    vector$lanes$0$exp_dl$stages$4 stages$4(
        .d(stages$4$d),
        .q(stages$4$q),
        .clock(stages$4$clock)
    );
    vector$lanes$0$exp_dl$stages$5 stages$5(
        .d(stages$5$d),
        .q(stages$5$q),
        .clock(stages$5$clock)
    );
    vector$lanes$0$exp_dl$stages$6 stages$6(
        .d(stages$6$d),
        .q(stages$6$q),
        .clock(stages$6$clock)
    );
    vector$lanes$0$exp_dl$stages$7 stages$7(
        .d(stages$7$d),
        .q(stages$7$q),
        .clock(stages$7$clock)
    );
    vector$lanes$0$exp_dl$stages$8 stages$8(
        .d(stages$8$d),
        .q(stages$8$q),
        .clock(stages$8$clock)
    );
    vector$lanes$0$exp_dl$stages$9 stages$9(
        .d(stages$9$d),
        .q(stages$9$q),
        .clock(stages$9$clock)
    );
    vector$lanes$0$exp_dl$stages$10 stages$10(
        .d(stages$10$d),
        .q(stages$10$q),
        .clock(stages$10$clock)
    );
    vector$lanes$0$exp_dl$stages$11 stages$11(
        .d(stages$11$d),
        .q(stages$11$q),
        .clock(stages$11$clock)
    );
    vector$lanes$0$exp_dl$stages$12 stages$12(
        .d(stages$12$d),
        .q(stages$12$q),
        .clock(stages$12$clock)
    );
    vector$lanes$0$exp_dl$stages$13 stages$13(
        .d(stages$13$d),
        .q(stages$13$q),
        .clock(stages$13$clock)
    );
    vector$lanes$0$exp_dl$stages$14 stages$14(
        .d(stages$14$d),
        .q(stages$14$q),
        .clock(stages$14$clock)
    );
    vector$lanes$0$exp_dl$stages$15 stages$15(
        .d(stages$15$d),
        .q(stages$15$q),
        .clock(stages$15$clock)
    );
    vector$lanes$0$exp_dl$stages$16 stages$16(
        .d(stages$16$d),
        .q(stages$16$q),
        .clock(stages$16$clock)
    );
    vector$lanes$0$exp_dl$stages$17 stages$17(
        .d(stages$17$d),
        .q(stages$17$q),
        .clock(stages$17$clock)
    );
    vector$lanes$0$exp_dl$stages$18 stages$18(
        .d(stages$18$d),
        .q(stages$18$q),
        .clock(stages$18$clock)
    );
    vector$lanes$0$exp_dl$stages$19 stages$19(
        .d(stages$19$d),
        .q(stages$19$q),
        .clock(stages$19$clock)
    );
    vector$lanes$0$exp_dl$stages$20 stages$20(
        .d(stages$20$d),
        .q(stages$20$q),
        .clock(stages$20$clock)
    );
    vector$lanes$0$exp_dl$stages$21 stages$21(
        .d(stages$21$d),
        .q(stages$21$q),
        .clock(stages$21$clock)
    );
    vector$lanes$0$exp_dl$stages$22 stages$22(
        .d(stages$22$d),
        .q(stages$22$q),
        .clock(stages$22$clock)
    );
    vector$lanes$0$exp_dl$stages$23 stages$23(
        .d(stages$23$d),
        .q(stages$23$q),
        .clock(stages$23$clock)
    );
    vector$lanes$0$exp_dl$stages$24 stages$24(
        .d(stages$24$d),
        .q(stages$24$q),
        .clock(stages$24$clock)
    );
    vector$lanes$0$exp_dl$stages$25 stages$25(
        .d(stages$25$d),
        .q(stages$25$q),
        .clock(stages$25$clock)
    );
    vector$lanes$0$exp_dl$stages$26 stages$26(
        .d(stages$26$d),
        .q(stages$26$q),
        .clock(stages$26$clock)
    );
    vector$lanes$0$exp_dl$stages$27 stages$27(
        .d(stages$27$d),
        .q(stages$27$q),
        .clock(stages$27$clock)
    );
    
    // Update code
    always @(*) begin
        stages$0$clock = clock;
        stages$0$d = stages$0$q;
        stages$1$clock = clock;
        stages$1$d = stages$1$q;
        stages$2$clock = clock;
        stages$2$d = stages$2$q;
        stages$3$clock = clock;
        stages$3$d = stages$3$q;
        stages$4$clock = clock;
        stages$4$d = stages$4$q;
        stages$5$clock = clock;
        stages$5$d = stages$5$q;
        stages$6$clock = clock;
        stages$6$d = stages$6$q;
        stages$7$clock = clock;
        stages$7$d = stages$7$q;
        stages$8$clock = clock;
        stages$8$d = stages$8$q;
        stages$9$clock = clock;
        stages$9$d = stages$9$q;
        stages$10$clock = clock;
        stages$10$d = stages$10$q;
        stages$11$clock = clock;
        stages$11$d = stages$11$q;
        stages$12$clock = clock;
        stages$12$d = stages$12$q;
        stages$13$clock = clock;
        stages$13$d = stages$13$q;
        stages$14$clock = clock;
        stages$14$d = stages$14$q;
        stages$15$clock = clock;
        stages$15$d = stages$15$q;
        stages$16$clock = clock;
        stages$16$d = stages$16$q;
        stages$17$clock = clock;
        stages$17$d = stages$17$q;
        stages$18$clock = clock;
        stages$18$d = stages$18$q;
        stages$19$clock = clock;
        stages$19$d = stages$19$q;
        stages$20$clock = clock;
        stages$20$d = stages$20$q;
        stages$21$clock = clock;
        stages$21$d = stages$21$q;
        stages$22$clock = clock;
        stages$22$d = stages$22$q;
        stages$23$clock = clock;
        stages$23$d = stages$23$q;
        stages$24$clock = clock;
        stages$24$d = stages$24$q;
        stages$25$clock = clock;
        stages$25$d = stages$25$q;
        stages$26$clock = clock;
        stages$26$d = stages$26$q;
        stages$27$clock = clock;
        stages$27$d = stages$27$q;
        if (en) begin
            stages$0$d = d;
            stages$1$d = stages$0$q;
            stages$2$d = stages$1$q;
            stages$3$d = stages$2$q;
            stages$4$d = stages$3$q;
            stages$5$d = stages$4$q;
            stages$6$d = stages$5$q;
            stages$7$d = stages$6$q;
            stages$8$d = stages$7$q;
            stages$9$d = stages$8$q;
            stages$10$d = stages$9$q;
            stages$11$d = stages$10$q;
            stages$12$d = stages$11$q;
            stages$13$d = stages$12$q;
            stages$14$d = stages$13$q;
            stages$15$d = stages$14$q;
            stages$16$d = stages$15$q;
            stages$17$d = stages$16$q;
            stages$18$d = stages$17$q;
            stages$19$d = stages$18$q;
            stages$20$d = stages$19$q;
            stages$21$d = stages$20$q;
            stages$22$d = stages$21$q;
            stages$23$d = stages$22$q;
            stages$24$d = stages$23$q;
            stages$25$d = stages$24$q;
            stages$26$d = stages$25$q;
            stages$27$d = stages$26$q;
        end
        q = stages$27$q;
    end
    
endmodule // vector$lanes$0$exp_dl


module vector$lanes$0$exp_dl$stages$0(d,q,clock);
    
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
          
endmodule // vector$lanes$0$exp_dl$stages$0


module vector$lanes$0$exp_dl$stages$1(d,q,clock);
    
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
          
endmodule // vector$lanes$0$exp_dl$stages$1


module vector$lanes$0$exp_dl$stages$10(d,q,clock);
    
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
          
endmodule // vector$lanes$0$exp_dl$stages$10


module vector$lanes$0$exp_dl$stages$11(d,q,clock);
    
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
          
endmodule // vector$lanes$0$exp_dl$stages$11


module vector$lanes$0$exp_dl$stages$12(d,q,clock);
    
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
          
endmodule // vector$lanes$0$exp_dl$stages$12


module vector$lanes$0$exp_dl$stages$13(d,q,clock);
    
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
          
endmodule // vector$lanes$0$exp_dl$stages$13


module vector$lanes$0$exp_dl$stages$14(d,q,clock);
    
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
          
endmodule // vector$lanes$0$exp_dl$stages$14


module vector$lanes$0$exp_dl$stages$15(d,q,clock);
    
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
          
endmodule // vector$lanes$0$exp_dl$stages$15


module vector$lanes$0$exp_dl$stages$16(d,q,clock);
    
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
          
endmodule // vector$lanes$0$exp_dl$stages$16


module vector$lanes$0$exp_dl$stages$17(d,q,clock);
    
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
          
endmodule // vector$lanes$0$exp_dl$stages$17


module vector$lanes$0$exp_dl$stages$18(d,q,clock);
    
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
          
endmodule // vector$lanes$0$exp_dl$stages$18


module vector$lanes$0$exp_dl$stages$19(d,q,clock);
    
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
          
endmodule // vector$lanes$0$exp_dl$stages$19


module vector$lanes$0$exp_dl$stages$2(d,q,clock);
    
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
          
endmodule // vector$lanes$0$exp_dl$stages$2


module vector$lanes$0$exp_dl$stages$20(d,q,clock);
    
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
          
endmodule // vector$lanes$0$exp_dl$stages$20


module vector$lanes$0$exp_dl$stages$21(d,q,clock);
    
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
          
endmodule // vector$lanes$0$exp_dl$stages$21


module vector$lanes$0$exp_dl$stages$22(d,q,clock);
    
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
          
endmodule // vector$lanes$0$exp_dl$stages$22


module vector$lanes$0$exp_dl$stages$23(d,q,clock);
    
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
          
endmodule // vector$lanes$0$exp_dl$stages$23


module vector$lanes$0$exp_dl$stages$24(d,q,clock);
    
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
          
endmodule // vector$lanes$0$exp_dl$stages$24


module vector$lanes$0$exp_dl$stages$25(d,q,clock);
    
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
          
endmodule // vector$lanes$0$exp_dl$stages$25


module vector$lanes$0$exp_dl$stages$26(d,q,clock);
    
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
          
endmodule // vector$lanes$0$exp_dl$stages$26


module vector$lanes$0$exp_dl$stages$27(d,q,clock);
    
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
          
endmodule // vector$lanes$0$exp_dl$stages$27


module vector$lanes$0$exp_dl$stages$3(d,q,clock);
    
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
          
endmodule // vector$lanes$0$exp_dl$stages$3


module vector$lanes$0$exp_dl$stages$4(d,q,clock);
    
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
          
endmodule // vector$lanes$0$exp_dl$stages$4


module vector$lanes$0$exp_dl$stages$5(d,q,clock);
    
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
          
endmodule // vector$lanes$0$exp_dl$stages$5


module vector$lanes$0$exp_dl$stages$6(d,q,clock);
    
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
          
endmodule // vector$lanes$0$exp_dl$stages$6


module vector$lanes$0$exp_dl$stages$7(d,q,clock);
    
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
          
endmodule // vector$lanes$0$exp_dl$stages$7


module vector$lanes$0$exp_dl$stages$8(d,q,clock);
    
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
          
endmodule // vector$lanes$0$exp_dl$stages$8


module vector$lanes$0$exp_dl$stages$9(d,q,clock);
    
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
          
endmodule // vector$lanes$0$exp_dl$stages$9


module vector$lanes$0$ez0(x,y);
    
    // Module arguments
    input wire  [17:0] x;
    output reg  [18:0] y;
    
    // Constant declarations
    localparam  msb = 8'h11;
    localparam  ext = 19'b1000000000000000000;
    
    // Update code
    always @(*) begin
        y = ((x) & 19'h7ffff);
        if (x[msb]) begin
            y = ((x) & 19'h7ffff) | ext;
        end
    end
    
endmodule // vector$lanes$0$ez0


module vector$lanes$0$hit_dl(clock,en,d,q);
    
    // Module arguments
    input wire  clock;
    input wire  en;
    input wire  d;
    output reg  q;
    
    // Stub signals
    reg  stages$0$d;
    wire  stages$0$q;
    reg  stages$0$clock;
    reg  stages$1$d;
    wire  stages$1$q;
    reg  stages$1$clock;
    reg  stages$2$d;
    wire  stages$2$q;
    reg  stages$2$clock;
    reg  stages$3$d;
    wire  stages$3$q;
    reg  stages$3$clock;
    reg  stages$4$d;
    wire  stages$4$q;
    reg  stages$4$clock;
    reg  stages$5$d;
    wire  stages$5$q;
    reg  stages$5$clock;
    reg  stages$6$d;
    wire  stages$6$q;
    reg  stages$6$clock;
    reg  stages$7$d;
    wire  stages$7$q;
    reg  stages$7$clock;
    reg  stages$8$d;
    wire  stages$8$q;
    reg  stages$8$clock;
    reg  stages$9$d;
    wire  stages$9$q;
    reg  stages$9$clock;
    reg  stages$10$d;
    wire  stages$10$q;
    reg  stages$10$clock;
    reg  stages$11$d;
    wire  stages$11$q;
    reg  stages$11$clock;
    reg  stages$12$d;
    wire  stages$12$q;
    reg  stages$12$clock;
    reg  stages$13$d;
    wire  stages$13$q;
    reg  stages$13$clock;
    reg  stages$14$d;
    wire  stages$14$q;
    reg  stages$14$clock;
    reg  stages$15$d;
    wire  stages$15$q;
    reg  stages$15$clock;
    reg  stages$16$d;
    wire  stages$16$q;
    reg  stages$16$clock;
    reg  stages$17$d;
    wire  stages$17$q;
    reg  stages$17$clock;
    reg  stages$18$d;
    wire  stages$18$q;
    reg  stages$18$clock;
    reg  stages$19$d;
    wire  stages$19$q;
    reg  stages$19$clock;
    reg  stages$20$d;
    wire  stages$20$q;
    reg  stages$20$clock;
    reg  stages$21$d;
    wire  stages$21$q;
    reg  stages$21$clock;
    reg  stages$22$d;
    wire  stages$22$q;
    reg  stages$22$clock;
    reg  stages$23$d;
    wire  stages$23$q;
    reg  stages$23$clock;
    reg  stages$24$d;
    wire  stages$24$q;
    reg  stages$24$clock;
    reg  stages$25$d;
    wire  stages$25$q;
    reg  stages$25$clock;
    reg  stages$26$d;
    wire  stages$26$q;
    reg  stages$26$clock;
    reg  stages$27$d;
    wire  stages$27$q;
    reg  stages$27$clock;
    reg  stages$28$d;
    wire  stages$28$q;
    reg  stages$28$clock;
    reg  stages$29$d;
    wire  stages$29$q;
    reg  stages$29$clock;
    reg  stages$30$d;
    wire  stages$30$q;
    reg  stages$30$clock;
    reg  stages$31$d;
    wire  stages$31$q;
    reg  stages$31$clock;
    reg  stages$32$d;
    wire  stages$32$q;
    reg  stages$32$clock;
    reg  stages$33$d;
    wire  stages$33$q;
    reg  stages$33$clock;
    reg  stages$34$d;
    wire  stages$34$q;
    reg  stages$34$clock;
    reg  stages$35$d;
    wire  stages$35$q;
    reg  stages$35$clock;
    reg  stages$36$d;
    wire  stages$36$q;
    reg  stages$36$clock;
    reg  stages$37$d;
    wire  stages$37$q;
    reg  stages$37$clock;
    reg  stages$38$d;
    wire  stages$38$q;
    reg  stages$38$clock;
    reg  stages$39$d;
    wire  stages$39$q;
    reg  stages$39$clock;
    
    // Sub module instances
    vector$lanes$0$hit_dl$stages$0 stages$0(
        .d(stages$0$d),
        .q(stages$0$q),
        .clock(stages$0$clock)
    );
    vector$lanes$0$hit_dl$stages$1 stages$1(
        .d(stages$1$d),
        .q(stages$1$q),
        .clock(stages$1$clock)
    );
    vector$lanes$0$hit_dl$stages$2 stages$2(
        .d(stages$2$d),
        .q(stages$2$q),
        .clock(stages$2$clock)
    );
    vector$lanes$0$hit_dl$stages$3 stages$3(
        .d(stages$3$d),
        .q(stages$3$q),
        .clock(stages$3$clock)
    );
    vector$lanes$0$hit_dl$stages$4 stages$4(
        .d(stages$4$d),
        .q(stages$4$q),
        .clock(stages$4$clock)
    );
    vector$lanes$0$hit_dl$stages$5 stages$5(
        .d(stages$5$d),
        .q(stages$5$q),
        .clock(stages$5$clock)
    );
    vector$lanes$0$hit_dl$stages$6 stages$6(
        .d(stages$6$d),
        .q(stages$6$q),
        .clock(stages$6$clock)
    );
    vector$lanes$0$hit_dl$stages$7 stages$7(
        .d(stages$7$d),
        .q(stages$7$q),
        .clock(stages$7$clock)
    );
    vector$lanes$0$hit_dl$stages$8 stages$8(
        .d(stages$8$d),
        .q(stages$8$q),
        .clock(stages$8$clock)
    );
    vector$lanes$0$hit_dl$stages$9 stages$9(
        .d(stages$9$d),
        .q(stages$9$q),
        .clock(stages$9$clock)
    );
    vector$lanes$0$hit_dl$stages$10 stages$10(
        .d(stages$10$d),
        .q(stages$10$q),
        .clock(stages$10$clock)
    );
    vector$lanes$0$hit_dl$stages$11 stages$11(
        .d(stages$11$d),
        .q(stages$11$q),
        .clock(stages$11$clock)
    );
    vector$lanes$0$hit_dl$stages$12 stages$12(
        .d(stages$12$d),
        .q(stages$12$q),
        .clock(stages$12$clock)
    );
    vector$lanes$0$hit_dl$stages$13 stages$13(
        .d(stages$13$d),
        .q(stages$13$q),
        .clock(stages$13$clock)
    );
    vector$lanes$0$hit_dl$stages$14 stages$14(
        .d(stages$14$d),
        .q(stages$14$q),
        .clock(stages$14$clock)
    );
    vector$lanes$0$hit_dl$stages$15 stages$15(
        .d(stages$15$d),
        .q(stages$15$q),
        .clock(stages$15$clock)
    );
    vector$lanes$0$hit_dl$stages$16 stages$16(
        .d(stages$16$d),
        .q(stages$16$q),
        .clock(stages$16$clock)
    );
    vector$lanes$0$hit_dl$stages$17 stages$17(
        .d(stages$17$d),
        .q(stages$17$q),
        .clock(stages$17$clock)
    );
    vector$lanes$0$hit_dl$stages$18 stages$18(
        .d(stages$18$d),
        .q(stages$18$q),
        .clock(stages$18$clock)
    );
    vector$lanes$0$hit_dl$stages$19 stages$19(
        .d(stages$19$d),
        .q(stages$19$q),
        .clock(stages$19$clock)
    );
    vector$lanes$0$hit_dl$stages$20 stages$20(
        .d(stages$20$d),
        .q(stages$20$q),
        .clock(stages$20$clock)
    );
    vector$lanes$0$hit_dl$stages$21 stages$21(
        .d(stages$21$d),
        .q(stages$21$q),
        .clock(stages$21$clock)
    );
    vector$lanes$0$hit_dl$stages$22 stages$22(
        .d(stages$22$d),
        .q(stages$22$q),
        .clock(stages$22$clock)
    );
    vector$lanes$0$hit_dl$stages$23 stages$23(
        .d(stages$23$d),
        .q(stages$23$q),
        .clock(stages$23$clock)
    );
    vector$lanes$0$hit_dl$stages$24 stages$24(
        .d(stages$24$d),
        .q(stages$24$q),
        .clock(stages$24$clock)
    );
    vector$lanes$0$hit_dl$stages$25 stages$25(
        .d(stages$25$d),
        .q(stages$25$q),
        .clock(stages$25$clock)
    );
    vector$lanes$0$hit_dl$stages$26 stages$26(
        .d(stages$26$d),
        .q(stages$26$q),
        .clock(stages$26$clock)
    );
    vector$lanes$0$hit_dl$stages$27 stages$27(
        .d(stages$27$d),
        .q(stages$27$q),
        .clock(stages$27$clock)
    );
    vector$lanes$0$hit_dl$stages$28 stages$28(
        .d(stages$28$d),
        .q(stages$28$q),
        .clock(stages$28$clock)
    );
    vector$lanes$0$hit_dl$stages$29 stages$29(
        .d(stages$29$d),
        .q(stages$29$q),
        .clock(stages$29$clock)
    );
    vector$lanes$0$hit_dl$stages$30 stages$30(
        .d(stages$30$d),
        .q(stages$30$q),
        .clock(stages$30$clock)
    );
    vector$lanes$0$hit_dl$stages$31 stages$31(
        .d(stages$31$d),
        .q(stages$31$q),
        .clock(stages$31$clock)
    );
    vector$lanes$0$hit_dl$stages$32 stages$32(
        .d(stages$32$d),
        .q(stages$32$q),
        .clock(stages$32$clock)
    );
    vector$lanes$0$hit_dl$stages$33 stages$33(
        .d(stages$33$d),
        .q(stages$33$q),
        .clock(stages$33$clock)
    );
    vector$lanes$0$hit_dl$stages$34 stages$34(
        .d(stages$34$d),
        .q(stages$34$q),
        .clock(stages$34$clock)
    );
    vector$lanes$0$hit_dl$stages$35 stages$35(
        .d(stages$35$d),
        .q(stages$35$q),
        .clock(stages$35$clock)
    );
    vector$lanes$0$hit_dl$stages$36 stages$36(
        .d(stages$36$d),
        .q(stages$36$q),
        .clock(stages$36$clock)
    );
    vector$lanes$0$hit_dl$stages$37 stages$37(
        .d(stages$37$d),
        .q(stages$37$q),
        .clock(stages$37$clock)
    );
    vector$lanes$0$hit_dl$stages$38 stages$38(
        .d(stages$38$d),
        .q(stages$38$q),
        .clock(stages$38$clock)
    );
    vector$lanes$0$hit_dl$stages$39 stages$39(
        .d(stages$39$d),
        .q(stages$39$q),
        .clock(stages$39$clock)
    );
    
    // Update code
    always @(*) begin
        stages$0$clock = clock;
        stages$0$d = stages$0$q;
        stages$1$clock = clock;
        stages$1$d = stages$1$q;
        stages$2$clock = clock;
        stages$2$d = stages$2$q;
        stages$3$clock = clock;
        stages$3$d = stages$3$q;
        stages$4$clock = clock;
        stages$4$d = stages$4$q;
        stages$5$clock = clock;
        stages$5$d = stages$5$q;
        stages$6$clock = clock;
        stages$6$d = stages$6$q;
        stages$7$clock = clock;
        stages$7$d = stages$7$q;
        stages$8$clock = clock;
        stages$8$d = stages$8$q;
        stages$9$clock = clock;
        stages$9$d = stages$9$q;
        stages$10$clock = clock;
        stages$10$d = stages$10$q;
        stages$11$clock = clock;
        stages$11$d = stages$11$q;
        stages$12$clock = clock;
        stages$12$d = stages$12$q;
        stages$13$clock = clock;
        stages$13$d = stages$13$q;
        stages$14$clock = clock;
        stages$14$d = stages$14$q;
        stages$15$clock = clock;
        stages$15$d = stages$15$q;
        stages$16$clock = clock;
        stages$16$d = stages$16$q;
        stages$17$clock = clock;
        stages$17$d = stages$17$q;
        stages$18$clock = clock;
        stages$18$d = stages$18$q;
        stages$19$clock = clock;
        stages$19$d = stages$19$q;
        stages$20$clock = clock;
        stages$20$d = stages$20$q;
        stages$21$clock = clock;
        stages$21$d = stages$21$q;
        stages$22$clock = clock;
        stages$22$d = stages$22$q;
        stages$23$clock = clock;
        stages$23$d = stages$23$q;
        stages$24$clock = clock;
        stages$24$d = stages$24$q;
        stages$25$clock = clock;
        stages$25$d = stages$25$q;
        stages$26$clock = clock;
        stages$26$d = stages$26$q;
        stages$27$clock = clock;
        stages$27$d = stages$27$q;
        stages$28$clock = clock;
        stages$28$d = stages$28$q;
        stages$29$clock = clock;
        stages$29$d = stages$29$q;
        stages$30$clock = clock;
        stages$30$d = stages$30$q;
        stages$31$clock = clock;
        stages$31$d = stages$31$q;
        stages$32$clock = clock;
        stages$32$d = stages$32$q;
        stages$33$clock = clock;
        stages$33$d = stages$33$q;
        stages$34$clock = clock;
        stages$34$d = stages$34$q;
        stages$35$clock = clock;
        stages$35$d = stages$35$q;
        stages$36$clock = clock;
        stages$36$d = stages$36$q;
        stages$37$clock = clock;
        stages$37$d = stages$37$q;
        stages$38$clock = clock;
        stages$38$d = stages$38$q;
        stages$39$clock = clock;
        stages$39$d = stages$39$q;
        if (en) begin
            stages$0$d = d;
            stages$1$d = stages$0$q;
            stages$2$d = stages$1$q;
            stages$3$d = stages$2$q;
            stages$4$d = stages$3$q;
            stages$5$d = stages$4$q;
            stages$6$d = stages$5$q;
            stages$7$d = stages$6$q;
            stages$8$d = stages$7$q;
            stages$9$d = stages$8$q;
            stages$10$d = stages$9$q;
            stages$11$d = stages$10$q;
            stages$12$d = stages$11$q;
            stages$13$d = stages$12$q;
            stages$14$d = stages$13$q;
            stages$15$d = stages$14$q;
            stages$16$d = stages$15$q;
            stages$17$d = stages$16$q;
            stages$18$d = stages$17$q;
            stages$19$d = stages$18$q;
            stages$20$d = stages$19$q;
            stages$21$d = stages$20$q;
            stages$22$d = stages$21$q;
            stages$23$d = stages$22$q;
            stages$24$d = stages$23$q;
            stages$25$d = stages$24$q;
            stages$26$d = stages$25$q;
            stages$27$d = stages$26$q;
            stages$28$d = stages$27$q;
            stages$29$d = stages$28$q;
            stages$30$d = stages$29$q;
            stages$31$d = stages$30$q;
            stages$32$d = stages$31$q;
            stages$33$d = stages$32$q;
            stages$34$d = stages$33$q;
            stages$35$d = stages$34$q;
            stages$36$d = stages$35$q;
            stages$37$d = stages$36$q;
            stages$38$d = stages$37$q;
            stages$39$d = stages$38$q;
        end
        q = stages$39$q;
    end
    
endmodule // vector$lanes$0$hit_dl


module vector$lanes$0$hit_dl$stages$0(d,q,clock);
    
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
          
endmodule // vector$lanes$0$hit_dl$stages$0


module vector$lanes$0$hit_dl$stages$1(d,q,clock);
    
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
          
endmodule // vector$lanes$0$hit_dl$stages$1


module vector$lanes$0$hit_dl$stages$10(d,q,clock);
    
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
          
endmodule // vector$lanes$0$hit_dl$stages$10


module vector$lanes$0$hit_dl$stages$11(d,q,clock);
    
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
          
endmodule // vector$lanes$0$hit_dl$stages$11


module vector$lanes$0$hit_dl$stages$12(d,q,clock);
    
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
          
endmodule // vector$lanes$0$hit_dl$stages$12


module vector$lanes$0$hit_dl$stages$13(d,q,clock);
    
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
          
endmodule // vector$lanes$0$hit_dl$stages$13


module vector$lanes$0$hit_dl$stages$14(d,q,clock);
    
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
          
endmodule // vector$lanes$0$hit_dl$stages$14


module vector$lanes$0$hit_dl$stages$15(d,q,clock);
    
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
          
endmodule // vector$lanes$0$hit_dl$stages$15


module vector$lanes$0$hit_dl$stages$16(d,q,clock);
    
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
          
endmodule // vector$lanes$0$hit_dl$stages$16


module vector$lanes$0$hit_dl$stages$17(d,q,clock);
    
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
          
endmodule // vector$lanes$0$hit_dl$stages$17


module vector$lanes$0$hit_dl$stages$18(d,q,clock);
    
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
          
endmodule // vector$lanes$0$hit_dl$stages$18


module vector$lanes$0$hit_dl$stages$19(d,q,clock);
    
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
          
endmodule // vector$lanes$0$hit_dl$stages$19


module vector$lanes$0$hit_dl$stages$2(d,q,clock);
    
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
          
endmodule // vector$lanes$0$hit_dl$stages$2


module vector$lanes$0$hit_dl$stages$20(d,q,clock);
    
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
          
endmodule // vector$lanes$0$hit_dl$stages$20


module vector$lanes$0$hit_dl$stages$21(d,q,clock);
    
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
          
endmodule // vector$lanes$0$hit_dl$stages$21


module vector$lanes$0$hit_dl$stages$22(d,q,clock);
    
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
          
endmodule // vector$lanes$0$hit_dl$stages$22


module vector$lanes$0$hit_dl$stages$23(d,q,clock);
    
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
          
endmodule // vector$lanes$0$hit_dl$stages$23


module vector$lanes$0$hit_dl$stages$24(d,q,clock);
    
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
          
endmodule // vector$lanes$0$hit_dl$stages$24


module vector$lanes$0$hit_dl$stages$25(d,q,clock);
    
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
          
endmodule // vector$lanes$0$hit_dl$stages$25


module vector$lanes$0$hit_dl$stages$26(d,q,clock);
    
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
          
endmodule // vector$lanes$0$hit_dl$stages$26


module vector$lanes$0$hit_dl$stages$27(d,q,clock);
    
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
          
endmodule // vector$lanes$0$hit_dl$stages$27


module vector$lanes$0$hit_dl$stages$28(d,q,clock);
    
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
          
endmodule // vector$lanes$0$hit_dl$stages$28


module vector$lanes$0$hit_dl$stages$29(d,q,clock);
    
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
          
endmodule // vector$lanes$0$hit_dl$stages$29


module vector$lanes$0$hit_dl$stages$3(d,q,clock);
    
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
          
endmodule // vector$lanes$0$hit_dl$stages$3


module vector$lanes$0$hit_dl$stages$30(d,q,clock);
    
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
          
endmodule // vector$lanes$0$hit_dl$stages$30


module vector$lanes$0$hit_dl$stages$31(d,q,clock);
    
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
          
endmodule // vector$lanes$0$hit_dl$stages$31


module vector$lanes$0$hit_dl$stages$32(d,q,clock);
    
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
          
endmodule // vector$lanes$0$hit_dl$stages$32


module vector$lanes$0$hit_dl$stages$33(d,q,clock);
    
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
          
endmodule // vector$lanes$0$hit_dl$stages$33


module vector$lanes$0$hit_dl$stages$34(d,q,clock);
    
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
          
endmodule // vector$lanes$0$hit_dl$stages$34


module vector$lanes$0$hit_dl$stages$35(d,q,clock);
    
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
          
endmodule // vector$lanes$0$hit_dl$stages$35


module vector$lanes$0$hit_dl$stages$36(d,q,clock);
    
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
          
endmodule // vector$lanes$0$hit_dl$stages$36


module vector$lanes$0$hit_dl$stages$37(d,q,clock);
    
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
          
endmodule // vector$lanes$0$hit_dl$stages$37


module vector$lanes$0$hit_dl$stages$38(d,q,clock);
    
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
          
endmodule // vector$lanes$0$hit_dl$stages$38


module vector$lanes$0$hit_dl$stages$39(d,q,clock);
    
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
          
endmodule // vector$lanes$0$hit_dl$stages$39


module vector$lanes$0$hit_dl$stages$4(d,q,clock);
    
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
          
endmodule // vector$lanes$0$hit_dl$stages$4


module vector$lanes$0$hit_dl$stages$5(d,q,clock);
    
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
          
endmodule // vector$lanes$0$hit_dl$stages$5


module vector$lanes$0$hit_dl$stages$6(d,q,clock);
    
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
          
endmodule // vector$lanes$0$hit_dl$stages$6


module vector$lanes$0$hit_dl$stages$7(d,q,clock);
    
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
          
endmodule // vector$lanes$0$hit_dl$stages$7


module vector$lanes$0$hit_dl$stages$8(d,q,clock);
    
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
          
endmodule // vector$lanes$0$hit_dl$stages$8


module vector$lanes$0$hit_dl$stages$9(d,q,clock);
    
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
          
endmodule // vector$lanes$0$hit_dl$stages$9


module vector$lanes$0$lead_s(x,pos);
    
    // Module arguments
    input wire  [29:0] x;
    output reg  [7:0] pos;
    
    // Constant declarations
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
    
    // Update code
    always @(*) begin
        pos = 32'h0;
        if (x[0]) begin
            pos = index$0;
        end
        if (x[1]) begin
            pos = index$1;
        end
        if (x[2]) begin
            pos = index$2;
        end
        if (x[3]) begin
            pos = index$3;
        end
        if (x[4]) begin
            pos = index$4;
        end
        if (x[5]) begin
            pos = index$5;
        end
        if (x[6]) begin
            pos = index$6;
        end
        if (x[7]) begin
            pos = index$7;
        end
        if (x[8]) begin
            pos = index$8;
        end
        if (x[9]) begin
            pos = index$9;
        end
        if (x[10]) begin
            pos = index$10;
        end
        if (x[11]) begin
            pos = index$11;
        end
        if (x[12]) begin
            pos = index$12;
        end
        if (x[13]) begin
            pos = index$13;
        end
        if (x[14]) begin
            pos = index$14;
        end
        if (x[15]) begin
            pos = index$15;
        end
        if (x[16]) begin
            pos = index$16;
        end
        if (x[17]) begin
            pos = index$17;
        end
        if (x[18]) begin
            pos = index$18;
        end
        if (x[19]) begin
            pos = index$19;
        end
        if (x[20]) begin
            pos = index$20;
        end
        if (x[21]) begin
            pos = index$21;
        end
        if (x[22]) begin
            pos = index$22;
        end
        if (x[23]) begin
            pos = index$23;
        end
        if (x[24]) begin
            pos = index$24;
        end
        if (x[25]) begin
            pos = index$25;
        end
        if (x[26]) begin
            pos = index$26;
        end
        if (x[27]) begin
            pos = index$27;
        end
        if (x[28]) begin
            pos = index$28;
        end
        if (x[29]) begin
            pos = index$29;
        end
    end
    
endmodule // vector$lanes$0$lead_s


module vector$lanes$0$mul_a(clock,en,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  en;
    input wire  [34:0] a;
    input wire  [25:0] b;
    output reg  [60:0] p;
    
    // Stub signals
    reg  [34:0] a_r$d;
    wire  [34:0] a_r$q;
    reg  a_r$clock;
    reg  [25:0] b_r$d;
    wire  [25:0] b_r$q;
    reg  b_r$clock;
    reg  [60:0] p_r$d;
    wire  [60:0] p_r$q;
    reg  p_r$clock;
    reg  [34:0] mul$a;
    reg  [25:0] mul$b;
    wire  [60:0] mul$p;
    
    // Sub module instances
    vector$lanes$0$mul_a$a_r a_r(
        .d(a_r$d),
        .q(a_r$q),
        .clock(a_r$clock)
    );
    vector$lanes$0$mul_a$b_r b_r(
        .d(b_r$d),
        .q(b_r$q),
        .clock(b_r$clock)
    );
    vector$lanes$0$mul_a$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$lanes$0$mul_a$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        a_r$clock = clock;
        b_r$clock = clock;
        p_r$clock = clock;
        a_r$d = a_r$q;
        b_r$d = b_r$q;
        p_r$d = p_r$q;
        mul$a = a_r$q;
        mul$b = b_r$q;
        if (en) begin
            a_r$d = a;
            b_r$d = b;
            p_r$d = mul$p;
        end
        p = p_r$q;
    end
    
endmodule // vector$lanes$0$mul_a


module vector$lanes$0$mul_a$a_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$mul_a$a_r


module vector$lanes$0$mul_a$b_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$mul_a$b_r


module vector$lanes$0$mul_a$mul(a,b,p);
    
    // Module arguments
    input wire  [34:0] a;
    input wire  [25:0] b;
    output reg  [60:0] p;
    
    // Update code (custom)
    // p = low 61 bits of a * b, both signed: a signed 61-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // vector$lanes$0$mul_a$mul


module vector$lanes$0$mul_a$p_r(d,q,clock);
    
    // Module arguments
    input wire  [60:0] d;
    output reg  [60:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 61'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$mul_a$p_r


module vector$lanes$0$mul_b(clock,en,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  en;
    input wire  [34:0] a;
    input wire  [25:0] b;
    output reg  [60:0] p;
    
    // Stub signals
    reg  [34:0] a_r$d;
    wire  [34:0] a_r$q;
    reg  a_r$clock;
    reg  [25:0] b_r$d;
    wire  [25:0] b_r$q;
    reg  b_r$clock;
    reg  [60:0] p_r$d;
    wire  [60:0] p_r$q;
    reg  p_r$clock;
    reg  [34:0] mul$a;
    reg  [25:0] mul$b;
    wire  [60:0] mul$p;
    
    // Sub module instances
    vector$lanes$0$mul_b$a_r a_r(
        .d(a_r$d),
        .q(a_r$q),
        .clock(a_r$clock)
    );
    vector$lanes$0$mul_b$b_r b_r(
        .d(b_r$d),
        .q(b_r$q),
        .clock(b_r$clock)
    );
    vector$lanes$0$mul_b$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$lanes$0$mul_b$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        a_r$clock = clock;
        b_r$clock = clock;
        p_r$clock = clock;
        a_r$d = a_r$q;
        b_r$d = b_r$q;
        p_r$d = p_r$q;
        mul$a = a_r$q;
        mul$b = b_r$q;
        if (en) begin
            a_r$d = a;
            b_r$d = b;
            p_r$d = mul$p;
        end
        p = p_r$q;
    end
    
endmodule // vector$lanes$0$mul_b


module vector$lanes$0$mul_b$a_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$mul_b$a_r


module vector$lanes$0$mul_b$b_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$mul_b$b_r


module vector$lanes$0$mul_b$mul(a,b,p);
    
    // Module arguments
    input wire  [34:0] a;
    input wire  [25:0] b;
    output reg  [60:0] p;
    
    // Update code (custom)
    // p = low 61 bits of a * b, both signed: a signed 61-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // vector$lanes$0$mul_b$mul


module vector$lanes$0$mul_b$p_r(d,q,clock);
    
    // Module arguments
    input wire  [60:0] d;
    output reg  [60:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 61'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$mul_b$p_r


module vector$lanes$0$mul_c1$0(clock,en,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  en;
    input wire  [8:0] a;
    input wire  [27:0] b;
    output reg  [37:0] p;
    
    // Stub signals
    reg  [8:0] a_r$d;
    wire  [8:0] a_r$q;
    reg  a_r$clock;
    reg  [27:0] b_r$d;
    wire  [27:0] b_r$q;
    reg  b_r$clock;
    reg  [37:0] p_r$d;
    wire  [37:0] p_r$q;
    reg  p_r$clock;
    reg  [8:0] mul$a;
    reg  [27:0] mul$b;
    wire  [37:0] mul$p;
    
    // Sub module instances
    vector$lanes$0$mul_c1$0$a_r a_r(
        .d(a_r$d),
        .q(a_r$q),
        .clock(a_r$clock)
    );
    vector$lanes$0$mul_c1$0$b_r b_r(
        .d(b_r$d),
        .q(b_r$q),
        .clock(b_r$clock)
    );
    vector$lanes$0$mul_c1$0$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$lanes$0$mul_c1$0$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        a_r$clock = clock;
        b_r$clock = clock;
        p_r$clock = clock;
        a_r$d = a_r$q;
        b_r$d = b_r$q;
        p_r$d = p_r$q;
        mul$a = a_r$q;
        mul$b = b_r$q;
        if (en) begin
            a_r$d = a;
            b_r$d = b;
            p_r$d = mul$p;
        end
        p = p_r$q;
    end
    
endmodule // vector$lanes$0$mul_c1$0


module vector$lanes$0$mul_c1$0$a_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$mul_c1$0$a_r


module vector$lanes$0$mul_c1$0$b_r(d,q,clock);
    
    // Module arguments
    input wire  [27:0] d;
    output reg  [27:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 28'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$mul_c1$0$b_r


module vector$lanes$0$mul_c1$0$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [27:0] b;
    output reg  [37:0] p;
    
    // Update code (custom)
    // p = low 38 bits of a * b, both signed: a signed 38-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // vector$lanes$0$mul_c1$0$mul


module vector$lanes$0$mul_c1$0$p_r(d,q,clock);
    
    // Module arguments
    input wire  [37:0] d;
    output reg  [37:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 38'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$mul_c1$0$p_r


module vector$lanes$0$mul_c1$1(clock,en,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  en;
    input wire  [8:0] a;
    input wire  [27:0] b;
    output reg  [37:0] p;
    
    // Stub signals
    reg  [8:0] a_r$d;
    wire  [8:0] a_r$q;
    reg  a_r$clock;
    reg  [27:0] b_r$d;
    wire  [27:0] b_r$q;
    reg  b_r$clock;
    reg  [37:0] p_r$d;
    wire  [37:0] p_r$q;
    reg  p_r$clock;
    reg  [8:0] mul$a;
    reg  [27:0] mul$b;
    wire  [37:0] mul$p;
    
    // Sub module instances
    vector$lanes$0$mul_c1$1$a_r a_r(
        .d(a_r$d),
        .q(a_r$q),
        .clock(a_r$clock)
    );
    vector$lanes$0$mul_c1$1$b_r b_r(
        .d(b_r$d),
        .q(b_r$q),
        .clock(b_r$clock)
    );
    vector$lanes$0$mul_c1$1$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$lanes$0$mul_c1$1$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        a_r$clock = clock;
        b_r$clock = clock;
        p_r$clock = clock;
        a_r$d = a_r$q;
        b_r$d = b_r$q;
        p_r$d = p_r$q;
        mul$a = a_r$q;
        mul$b = b_r$q;
        if (en) begin
            a_r$d = a;
            b_r$d = b;
            p_r$d = mul$p;
        end
        p = p_r$q;
    end
    
endmodule // vector$lanes$0$mul_c1$1


module vector$lanes$0$mul_c1$1$a_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$mul_c1$1$a_r


module vector$lanes$0$mul_c1$1$b_r(d,q,clock);
    
    // Module arguments
    input wire  [27:0] d;
    output reg  [27:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 28'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$mul_c1$1$b_r


module vector$lanes$0$mul_c1$1$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [27:0] b;
    output reg  [37:0] p;
    
    // Update code (custom)
    // p = low 38 bits of a * b, both signed: a signed 38-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // vector$lanes$0$mul_c1$1$mul


module vector$lanes$0$mul_c1$1$p_r(d,q,clock);
    
    // Module arguments
    input wire  [37:0] d;
    output reg  [37:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 38'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$mul_c1$1$p_r


module vector$lanes$0$mul_c1$2(clock,en,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  en;
    input wire  [8:0] a;
    input wire  [27:0] b;
    output reg  [37:0] p;
    
    // Stub signals
    reg  [8:0] a_r$d;
    wire  [8:0] a_r$q;
    reg  a_r$clock;
    reg  [27:0] b_r$d;
    wire  [27:0] b_r$q;
    reg  b_r$clock;
    reg  [37:0] p_r$d;
    wire  [37:0] p_r$q;
    reg  p_r$clock;
    reg  [8:0] mul$a;
    reg  [27:0] mul$b;
    wire  [37:0] mul$p;
    
    // Sub module instances
    vector$lanes$0$mul_c1$2$a_r a_r(
        .d(a_r$d),
        .q(a_r$q),
        .clock(a_r$clock)
    );
    vector$lanes$0$mul_c1$2$b_r b_r(
        .d(b_r$d),
        .q(b_r$q),
        .clock(b_r$clock)
    );
    vector$lanes$0$mul_c1$2$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$lanes$0$mul_c1$2$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        a_r$clock = clock;
        b_r$clock = clock;
        p_r$clock = clock;
        a_r$d = a_r$q;
        b_r$d = b_r$q;
        p_r$d = p_r$q;
        mul$a = a_r$q;
        mul$b = b_r$q;
        if (en) begin
            a_r$d = a;
            b_r$d = b;
            p_r$d = mul$p;
        end
        p = p_r$q;
    end
    
endmodule // vector$lanes$0$mul_c1$2


module vector$lanes$0$mul_c1$2$a_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$mul_c1$2$a_r


module vector$lanes$0$mul_c1$2$b_r(d,q,clock);
    
    // Module arguments
    input wire  [27:0] d;
    output reg  [27:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 28'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$mul_c1$2$b_r


module vector$lanes$0$mul_c1$2$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [27:0] b;
    output reg  [37:0] p;
    
    // Update code (custom)
    // p = low 38 bits of a * b, both signed: a signed 38-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // vector$lanes$0$mul_c1$2$mul


module vector$lanes$0$mul_c1$2$p_r(d,q,clock);
    
    // Module arguments
    input wire  [37:0] d;
    output reg  [37:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 38'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$mul_c1$2$p_r


module vector$lanes$0$mul_c2$0(clock,en,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  en;
    input wire  [8:0] a;
    input wire  [27:0] b;
    output reg  [37:0] p;
    
    // Stub signals
    reg  [8:0] a_r$d;
    wire  [8:0] a_r$q;
    reg  a_r$clock;
    reg  [27:0] b_r$d;
    wire  [27:0] b_r$q;
    reg  b_r$clock;
    reg  [37:0] p_r$d;
    wire  [37:0] p_r$q;
    reg  p_r$clock;
    reg  [8:0] mul$a;
    reg  [27:0] mul$b;
    wire  [37:0] mul$p;
    
    // Sub module instances
    vector$lanes$0$mul_c2$0$a_r a_r(
        .d(a_r$d),
        .q(a_r$q),
        .clock(a_r$clock)
    );
    vector$lanes$0$mul_c2$0$b_r b_r(
        .d(b_r$d),
        .q(b_r$q),
        .clock(b_r$clock)
    );
    vector$lanes$0$mul_c2$0$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$lanes$0$mul_c2$0$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        a_r$clock = clock;
        b_r$clock = clock;
        p_r$clock = clock;
        a_r$d = a_r$q;
        b_r$d = b_r$q;
        p_r$d = p_r$q;
        mul$a = a_r$q;
        mul$b = b_r$q;
        if (en) begin
            a_r$d = a;
            b_r$d = b;
            p_r$d = mul$p;
        end
        p = p_r$q;
    end
    
endmodule // vector$lanes$0$mul_c2$0


module vector$lanes$0$mul_c2$0$a_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$mul_c2$0$a_r


module vector$lanes$0$mul_c2$0$b_r(d,q,clock);
    
    // Module arguments
    input wire  [27:0] d;
    output reg  [27:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 28'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$mul_c2$0$b_r


module vector$lanes$0$mul_c2$0$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [27:0] b;
    output reg  [37:0] p;
    
    // Update code (custom)
    // p = low 38 bits of a * b, both signed: a signed 38-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // vector$lanes$0$mul_c2$0$mul


module vector$lanes$0$mul_c2$0$p_r(d,q,clock);
    
    // Module arguments
    input wire  [37:0] d;
    output reg  [37:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 38'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$mul_c2$0$p_r


module vector$lanes$0$mul_c2$1(clock,en,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  en;
    input wire  [8:0] a;
    input wire  [27:0] b;
    output reg  [37:0] p;
    
    // Stub signals
    reg  [8:0] a_r$d;
    wire  [8:0] a_r$q;
    reg  a_r$clock;
    reg  [27:0] b_r$d;
    wire  [27:0] b_r$q;
    reg  b_r$clock;
    reg  [37:0] p_r$d;
    wire  [37:0] p_r$q;
    reg  p_r$clock;
    reg  [8:0] mul$a;
    reg  [27:0] mul$b;
    wire  [37:0] mul$p;
    
    // Sub module instances
    vector$lanes$0$mul_c2$1$a_r a_r(
        .d(a_r$d),
        .q(a_r$q),
        .clock(a_r$clock)
    );
    vector$lanes$0$mul_c2$1$b_r b_r(
        .d(b_r$d),
        .q(b_r$q),
        .clock(b_r$clock)
    );
    vector$lanes$0$mul_c2$1$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$lanes$0$mul_c2$1$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        a_r$clock = clock;
        b_r$clock = clock;
        p_r$clock = clock;
        a_r$d = a_r$q;
        b_r$d = b_r$q;
        p_r$d = p_r$q;
        mul$a = a_r$q;
        mul$b = b_r$q;
        if (en) begin
            a_r$d = a;
            b_r$d = b;
            p_r$d = mul$p;
        end
        p = p_r$q;
    end
    
endmodule // vector$lanes$0$mul_c2$1


module vector$lanes$0$mul_c2$1$a_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$mul_c2$1$a_r


module vector$lanes$0$mul_c2$1$b_r(d,q,clock);
    
    // Module arguments
    input wire  [27:0] d;
    output reg  [27:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 28'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$mul_c2$1$b_r


module vector$lanes$0$mul_c2$1$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [27:0] b;
    output reg  [37:0] p;
    
    // Update code (custom)
    // p = low 38 bits of a * b, both signed: a signed 38-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // vector$lanes$0$mul_c2$1$mul


module vector$lanes$0$mul_c2$1$p_r(d,q,clock);
    
    // Module arguments
    input wire  [37:0] d;
    output reg  [37:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 38'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$mul_c2$1$p_r


module vector$lanes$0$mul_c2$2(clock,en,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  en;
    input wire  [8:0] a;
    input wire  [27:0] b;
    output reg  [37:0] p;
    
    // Stub signals
    reg  [8:0] a_r$d;
    wire  [8:0] a_r$q;
    reg  a_r$clock;
    reg  [27:0] b_r$d;
    wire  [27:0] b_r$q;
    reg  b_r$clock;
    reg  [37:0] p_r$d;
    wire  [37:0] p_r$q;
    reg  p_r$clock;
    reg  [8:0] mul$a;
    reg  [27:0] mul$b;
    wire  [37:0] mul$p;
    
    // Sub module instances
    vector$lanes$0$mul_c2$2$a_r a_r(
        .d(a_r$d),
        .q(a_r$q),
        .clock(a_r$clock)
    );
    vector$lanes$0$mul_c2$2$b_r b_r(
        .d(b_r$d),
        .q(b_r$q),
        .clock(b_r$clock)
    );
    vector$lanes$0$mul_c2$2$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$lanes$0$mul_c2$2$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        a_r$clock = clock;
        b_r$clock = clock;
        p_r$clock = clock;
        a_r$d = a_r$q;
        b_r$d = b_r$q;
        p_r$d = p_r$q;
        mul$a = a_r$q;
        mul$b = b_r$q;
        if (en) begin
            a_r$d = a;
            b_r$d = b;
            p_r$d = mul$p;
        end
        p = p_r$q;
    end
    
endmodule // vector$lanes$0$mul_c2$2


module vector$lanes$0$mul_c2$2$a_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$mul_c2$2$a_r


module vector$lanes$0$mul_c2$2$b_r(d,q,clock);
    
    // Module arguments
    input wire  [27:0] d;
    output reg  [27:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 28'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$mul_c2$2$b_r


module vector$lanes$0$mul_c2$2$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [27:0] b;
    output reg  [37:0] p;
    
    // Update code (custom)
    // p = low 38 bits of a * b, both signed: a signed 38-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // vector$lanes$0$mul_c2$2$mul


module vector$lanes$0$mul_c2$2$p_r(d,q,clock);
    
    // Module arguments
    input wire  [37:0] d;
    output reg  [37:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 38'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$mul_c2$2$p_r


module vector$lanes$0$mul_l$0(clock,en,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  en;
    input wire  [27:0] a;
    input wire  [16:0] b;
    output reg  [44:0] p;
    
    // Stub signals
    reg  [27:0] a_r$d;
    wire  [27:0] a_r$q;
    reg  a_r$clock;
    reg  [16:0] b_r$d;
    wire  [16:0] b_r$q;
    reg  b_r$clock;
    reg  [44:0] p_r$d;
    wire  [44:0] p_r$q;
    reg  p_r$clock;
    reg  [27:0] mul$a;
    reg  [16:0] mul$b;
    wire  [44:0] mul$p;
    
    // Sub module instances
    vector$lanes$0$mul_l$0$a_r a_r(
        .d(a_r$d),
        .q(a_r$q),
        .clock(a_r$clock)
    );
    vector$lanes$0$mul_l$0$b_r b_r(
        .d(b_r$d),
        .q(b_r$q),
        .clock(b_r$clock)
    );
    vector$lanes$0$mul_l$0$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$lanes$0$mul_l$0$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        a_r$clock = clock;
        b_r$clock = clock;
        p_r$clock = clock;
        a_r$d = a_r$q;
        b_r$d = b_r$q;
        p_r$d = p_r$q;
        mul$a = a_r$q;
        mul$b = b_r$q;
        if (en) begin
            a_r$d = a;
            b_r$d = b;
            p_r$d = mul$p;
        end
        p = p_r$q;
    end
    
endmodule // vector$lanes$0$mul_l$0


module vector$lanes$0$mul_l$0$a_r(d,q,clock);
    
    // Module arguments
    input wire  [27:0] d;
    output reg  [27:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 28'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$mul_l$0$a_r


module vector$lanes$0$mul_l$0$b_r(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$mul_l$0$b_r


module vector$lanes$0$mul_l$0$mul(a,b,p);
    
    // Module arguments
    input wire  [27:0] a;
    input wire  [16:0] b;
    output reg  [44:0] p;
    
    // Update code (custom)
    // p = low 45 bits of a * b, both signed: a signed 45-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // vector$lanes$0$mul_l$0$mul


module vector$lanes$0$mul_l$0$p_r(d,q,clock);
    
    // Module arguments
    input wire  [44:0] d;
    output reg  [44:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 45'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$mul_l$0$p_r


module vector$lanes$0$mul_l$1(clock,en,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  en;
    input wire  [27:0] a;
    input wire  [16:0] b;
    output reg  [44:0] p;
    
    // Stub signals
    reg  [27:0] a_r$d;
    wire  [27:0] a_r$q;
    reg  a_r$clock;
    reg  [16:0] b_r$d;
    wire  [16:0] b_r$q;
    reg  b_r$clock;
    reg  [44:0] p_r$d;
    wire  [44:0] p_r$q;
    reg  p_r$clock;
    reg  [27:0] mul$a;
    reg  [16:0] mul$b;
    wire  [44:0] mul$p;
    
    // Sub module instances
    vector$lanes$0$mul_l$1$a_r a_r(
        .d(a_r$d),
        .q(a_r$q),
        .clock(a_r$clock)
    );
    vector$lanes$0$mul_l$1$b_r b_r(
        .d(b_r$d),
        .q(b_r$q),
        .clock(b_r$clock)
    );
    vector$lanes$0$mul_l$1$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$lanes$0$mul_l$1$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        a_r$clock = clock;
        b_r$clock = clock;
        p_r$clock = clock;
        a_r$d = a_r$q;
        b_r$d = b_r$q;
        p_r$d = p_r$q;
        mul$a = a_r$q;
        mul$b = b_r$q;
        if (en) begin
            a_r$d = a;
            b_r$d = b;
            p_r$d = mul$p;
        end
        p = p_r$q;
    end
    
endmodule // vector$lanes$0$mul_l$1


module vector$lanes$0$mul_l$1$a_r(d,q,clock);
    
    // Module arguments
    input wire  [27:0] d;
    output reg  [27:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 28'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$mul_l$1$a_r


module vector$lanes$0$mul_l$1$b_r(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$mul_l$1$b_r


module vector$lanes$0$mul_l$1$mul(a,b,p);
    
    // Module arguments
    input wire  [27:0] a;
    input wire  [16:0] b;
    output reg  [44:0] p;
    
    // Update code (custom)
    // p = low 45 bits of a * b, both signed: a signed 45-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // vector$lanes$0$mul_l$1$mul


module vector$lanes$0$mul_l$1$p_r(d,q,clock);
    
    // Module arguments
    input wire  [44:0] d;
    output reg  [44:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 45'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$mul_l$1$p_r


module vector$lanes$0$mul_l$2(clock,en,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  en;
    input wire  [27:0] a;
    input wire  [16:0] b;
    output reg  [44:0] p;
    
    // Stub signals
    reg  [27:0] a_r$d;
    wire  [27:0] a_r$q;
    reg  a_r$clock;
    reg  [16:0] b_r$d;
    wire  [16:0] b_r$q;
    reg  b_r$clock;
    reg  [44:0] p_r$d;
    wire  [44:0] p_r$q;
    reg  p_r$clock;
    reg  [27:0] mul$a;
    reg  [16:0] mul$b;
    wire  [44:0] mul$p;
    
    // Sub module instances
    vector$lanes$0$mul_l$2$a_r a_r(
        .d(a_r$d),
        .q(a_r$q),
        .clock(a_r$clock)
    );
    vector$lanes$0$mul_l$2$b_r b_r(
        .d(b_r$d),
        .q(b_r$q),
        .clock(b_r$clock)
    );
    vector$lanes$0$mul_l$2$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$lanes$0$mul_l$2$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        a_r$clock = clock;
        b_r$clock = clock;
        p_r$clock = clock;
        a_r$d = a_r$q;
        b_r$d = b_r$q;
        p_r$d = p_r$q;
        mul$a = a_r$q;
        mul$b = b_r$q;
        if (en) begin
            a_r$d = a;
            b_r$d = b;
            p_r$d = mul$p;
        end
        p = p_r$q;
    end
    
endmodule // vector$lanes$0$mul_l$2


module vector$lanes$0$mul_l$2$a_r(d,q,clock);
    
    // Module arguments
    input wire  [27:0] d;
    output reg  [27:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 28'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$mul_l$2$a_r


module vector$lanes$0$mul_l$2$b_r(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$mul_l$2$b_r


module vector$lanes$0$mul_l$2$mul(a,b,p);
    
    // Module arguments
    input wire  [27:0] a;
    input wire  [16:0] b;
    output reg  [44:0] p;
    
    // Update code (custom)
    // p = low 45 bits of a * b, both signed: a signed 45-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // vector$lanes$0$mul_l$2$mul


module vector$lanes$0$mul_l$2$p_r(d,q,clock);
    
    // Module arguments
    input wire  [44:0] d;
    output reg  [44:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 45'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$mul_l$2$p_r


module vector$lanes$0$mul_ra(clock,en,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  en;
    input wire  [27:0] a;
    input wire  [25:0] b;
    output reg  [53:0] p;
    
    // Stub signals
    reg  [27:0] a_r$d;
    wire  [27:0] a_r$q;
    reg  a_r$clock;
    reg  [25:0] b_r$d;
    wire  [25:0] b_r$q;
    reg  b_r$clock;
    reg  [53:0] p_r$d;
    wire  [53:0] p_r$q;
    reg  p_r$clock;
    reg  [27:0] mul$a;
    reg  [25:0] mul$b;
    wire  [53:0] mul$p;
    
    // Sub module instances
    vector$lanes$0$mul_ra$a_r a_r(
        .d(a_r$d),
        .q(a_r$q),
        .clock(a_r$clock)
    );
    vector$lanes$0$mul_ra$b_r b_r(
        .d(b_r$d),
        .q(b_r$q),
        .clock(b_r$clock)
    );
    vector$lanes$0$mul_ra$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$lanes$0$mul_ra$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        a_r$clock = clock;
        b_r$clock = clock;
        p_r$clock = clock;
        a_r$d = a_r$q;
        b_r$d = b_r$q;
        p_r$d = p_r$q;
        mul$a = a_r$q;
        mul$b = b_r$q;
        if (en) begin
            a_r$d = a;
            b_r$d = b;
            p_r$d = mul$p;
        end
        p = p_r$q;
    end
    
endmodule // vector$lanes$0$mul_ra


module vector$lanes$0$mul_ra$a_r(d,q,clock);
    
    // Module arguments
    input wire  [27:0] d;
    output reg  [27:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 28'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$mul_ra$a_r


module vector$lanes$0$mul_ra$b_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$mul_ra$b_r


module vector$lanes$0$mul_ra$mul(a,b,p);
    
    // Module arguments
    input wire  [27:0] a;
    input wire  [25:0] b;
    output reg  [53:0] p;
    
    // Update code (custom)
    // p = low 54 bits of a * b, both signed: a signed 54-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // vector$lanes$0$mul_ra$mul


module vector$lanes$0$mul_ra$p_r(d,q,clock);
    
    // Module arguments
    input wire  [53:0] d;
    output reg  [53:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 54'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$mul_ra$p_r


module vector$lanes$0$mul_rb(clock,en,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  en;
    input wire  [27:0] a;
    input wire  [25:0] b;
    output reg  [53:0] p;
    
    // Stub signals
    reg  [27:0] a_r$d;
    wire  [27:0] a_r$q;
    reg  a_r$clock;
    reg  [25:0] b_r$d;
    wire  [25:0] b_r$q;
    reg  b_r$clock;
    reg  [53:0] p_r$d;
    wire  [53:0] p_r$q;
    reg  p_r$clock;
    reg  [27:0] mul$a;
    reg  [25:0] mul$b;
    wire  [53:0] mul$p;
    
    // Sub module instances
    vector$lanes$0$mul_rb$a_r a_r(
        .d(a_r$d),
        .q(a_r$q),
        .clock(a_r$clock)
    );
    vector$lanes$0$mul_rb$b_r b_r(
        .d(b_r$d),
        .q(b_r$q),
        .clock(b_r$clock)
    );
    vector$lanes$0$mul_rb$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$lanes$0$mul_rb$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        a_r$clock = clock;
        b_r$clock = clock;
        p_r$clock = clock;
        a_r$d = a_r$q;
        b_r$d = b_r$q;
        p_r$d = p_r$q;
        mul$a = a_r$q;
        mul$b = b_r$q;
        if (en) begin
            a_r$d = a;
            b_r$d = b;
            p_r$d = mul$p;
        end
        p = p_r$q;
    end
    
endmodule // vector$lanes$0$mul_rb


module vector$lanes$0$mul_rb$a_r(d,q,clock);
    
    // Module arguments
    input wire  [27:0] d;
    output reg  [27:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 28'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$mul_rb$a_r


module vector$lanes$0$mul_rb$b_r(d,q,clock);
    
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
          
endmodule // vector$lanes$0$mul_rb$b_r


module vector$lanes$0$mul_rb$mul(a,b,p);
    
    // Module arguments
    input wire  [27:0] a;
    input wire  [25:0] b;
    output reg  [53:0] p;
    
    // Update code (custom)
    // p = low 54 bits of a * b, both signed: a signed 54-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // vector$lanes$0$mul_rb$mul


module vector$lanes$0$mul_rb$p_r(d,q,clock);
    
    // Module arguments
    input wire  [53:0] d;
    output reg  [53:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 54'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$mul_rb$p_r


module vector$lanes$0$mul_z1(clock,en,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  en;
    input wire  [18:0] a;
    input wire  [27:0] b;
    output reg  [47:0] p;
    
    // Stub signals
    reg  [18:0] a_r$d;
    wire  [18:0] a_r$q;
    reg  a_r$clock;
    reg  [27:0] b_r$d;
    wire  [27:0] b_r$q;
    reg  b_r$clock;
    reg  [47:0] p_r$d;
    wire  [47:0] p_r$q;
    reg  p_r$clock;
    reg  [18:0] mul$a;
    reg  [27:0] mul$b;
    wire  [47:0] mul$p;
    
    // Sub module instances
    vector$lanes$0$mul_z1$a_r a_r(
        .d(a_r$d),
        .q(a_r$q),
        .clock(a_r$clock)
    );
    vector$lanes$0$mul_z1$b_r b_r(
        .d(b_r$d),
        .q(b_r$q),
        .clock(b_r$clock)
    );
    vector$lanes$0$mul_z1$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$lanes$0$mul_z1$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        a_r$clock = clock;
        b_r$clock = clock;
        p_r$clock = clock;
        a_r$d = a_r$q;
        b_r$d = b_r$q;
        p_r$d = p_r$q;
        mul$a = a_r$q;
        mul$b = b_r$q;
        if (en) begin
            a_r$d = a;
            b_r$d = b;
            p_r$d = mul$p;
        end
        p = p_r$q;
    end
    
endmodule // vector$lanes$0$mul_z1


module vector$lanes$0$mul_z1$a_r(d,q,clock);
    
    // Module arguments
    input wire  [18:0] d;
    output reg  [18:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 19'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$mul_z1$a_r


module vector$lanes$0$mul_z1$b_r(d,q,clock);
    
    // Module arguments
    input wire  [27:0] d;
    output reg  [27:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 28'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$mul_z1$b_r


module vector$lanes$0$mul_z1$mul(a,b,p);
    
    // Module arguments
    input wire  [18:0] a;
    input wire  [27:0] b;
    output reg  [47:0] p;
    
    // Update code (custom)
    // p = low 48 bits of a * b, both signed: a signed 48-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // vector$lanes$0$mul_z1$mul


module vector$lanes$0$mul_z1$p_r(d,q,clock);
    
    // Module arguments
    input wire  [47:0] d;
    output reg  [47:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 48'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$mul_z1$p_r


module vector$lanes$0$mul_z2(clock,en,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  en;
    input wire  [18:0] a;
    input wire  [27:0] b;
    output reg  [47:0] p;
    
    // Stub signals
    reg  [18:0] a_r$d;
    wire  [18:0] a_r$q;
    reg  a_r$clock;
    reg  [27:0] b_r$d;
    wire  [27:0] b_r$q;
    reg  b_r$clock;
    reg  [47:0] p_r$d;
    wire  [47:0] p_r$q;
    reg  p_r$clock;
    reg  [18:0] mul$a;
    reg  [27:0] mul$b;
    wire  [47:0] mul$p;
    
    // Sub module instances
    vector$lanes$0$mul_z2$a_r a_r(
        .d(a_r$d),
        .q(a_r$q),
        .clock(a_r$clock)
    );
    vector$lanes$0$mul_z2$b_r b_r(
        .d(b_r$d),
        .q(b_r$q),
        .clock(b_r$clock)
    );
    vector$lanes$0$mul_z2$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$lanes$0$mul_z2$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        a_r$clock = clock;
        b_r$clock = clock;
        p_r$clock = clock;
        a_r$d = a_r$q;
        b_r$d = b_r$q;
        p_r$d = p_r$q;
        mul$a = a_r$q;
        mul$b = b_r$q;
        if (en) begin
            a_r$d = a;
            b_r$d = b;
            p_r$d = mul$p;
        end
        p = p_r$q;
    end
    
endmodule // vector$lanes$0$mul_z2


module vector$lanes$0$mul_z2$a_r(d,q,clock);
    
    // Module arguments
    input wire  [18:0] d;
    output reg  [18:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 19'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$mul_z2$a_r


module vector$lanes$0$mul_z2$b_r(d,q,clock);
    
    // Module arguments
    input wire  [27:0] d;
    output reg  [27:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 28'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$mul_z2$b_r


module vector$lanes$0$mul_z2$mul(a,b,p);
    
    // Module arguments
    input wire  [18:0] a;
    input wire  [27:0] b;
    output reg  [47:0] p;
    
    // Update code (custom)
    // p = low 48 bits of a * b, both signed: a signed 48-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // vector$lanes$0$mul_z2$mul


module vector$lanes$0$mul_z2$p_r(d,q,clock);
    
    // Module arguments
    input wire  [47:0] d;
    output reg  [47:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 48'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$mul_z2$p_r


module vector$lanes$0$norm_s(x,exp,d);
    
    // Module arguments
    input wire  [29:0] x;
    input wire  [7:0] exp;
    output reg  [33:0] d;
    
    // Constant declarations
    localparam  top = 8'h20;
    
    // Local signals
    reg  [7:0] lsh;
    reg  [7:0] rsh;
    reg  [33:0] wide;
    
    // Update code
    always @(*) begin
        lsh = top - exp;
        rsh = 32'h0;
        if (exp > top) begin
            lsh = 32'h0;
            rsh = exp - top;
        end
        wide = (((x) & 34'h3ffffffff) << lsh) >> rsh;
        d = ((wide) & 34'h3ffffffff);
    end
    
endmodule // vector$lanes$0$norm_s


module vector$lanes$0$off$0(d,q,clock);
    
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
          
endmodule // vector$lanes$0$off$0


module vector$lanes$0$off$1(d,q,clock);
    
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
          
endmodule // vector$lanes$0$off$1


module vector$lanes$0$off$2(d,q,clock);
    
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
          
endmodule // vector$lanes$0$off$2


module vector$lanes$0$orgb$0(d,q,clock);
    
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
          
endmodule // vector$lanes$0$orgb$0


module vector$lanes$0$orgb$1(d,q,clock);
    
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
          
endmodule // vector$lanes$0$orgb$1


module vector$lanes$0$orgb$2(d,q,clock);
    
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
          
endmodule // vector$lanes$0$orgb$2


module vector$lanes$0$ov(d,q,clock);
    
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
          
endmodule // vector$lanes$0$ov


module vector$lanes$0$oz(d,q,clock);
    
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
          
endmodule // vector$lanes$0$oz


module vector$lanes$0$persp(on);
    
    // Module arguments
    output reg  on;
    
    // Constant declarations
    localparam  value = 1'b1;
    
    // Update code
    always @(*) begin
        on = value;
    end
    
endmodule // vector$lanes$0$persp


module vector$lanes$0$q6$0(d,q,clock);
    
    // Module arguments
    input wire  [27:0] d;
    output reg  [27:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 28'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$q6$0


module vector$lanes$0$q6$1(d,q,clock);
    
    // Module arguments
    input wire  [27:0] d;
    output reg  [27:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 28'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$q6$1


module vector$lanes$0$q6$2(d,q,clock);
    
    // Module arguments
    input wire  [27:0] d;
    output reg  [27:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 28'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$q6$2


module vector$lanes$0$q_dl(clock,en,d,q);
    
    // Module arguments
    input wire  clock;
    input wire  en;
    input wire  [55:0] d;
    output reg  [55:0] q;
    
    // Stub signals
    reg  [55:0] stages$0$d;
    wire  [55:0] stages$0$q;
    reg  stages$0$clock;
    reg  [55:0] stages$1$d;
    wire  [55:0] stages$1$q;
    reg  stages$1$clock;
    reg  [55:0] stages$2$d;
    wire  [55:0] stages$2$q;
    reg  stages$2$clock;
    reg  [55:0] stages$3$d;
    wire  [55:0] stages$3$q;
    reg  stages$3$clock;
    reg  [55:0] stages$4$d;
    wire  [55:0] stages$4$q;
    reg  stages$4$clock;
    reg  [55:0] stages$5$d;
    wire  [55:0] stages$5$q;
    reg  stages$5$clock;
    reg  [55:0] stages$6$d;
    wire  [55:0] stages$6$q;
    reg  stages$6$clock;
    reg  [55:0] stages$7$d;
    wire  [55:0] stages$7$q;
    reg  stages$7$clock;
    reg  [55:0] stages$8$d;
    wire  [55:0] stages$8$q;
    reg  stages$8$clock;
    reg  [55:0] stages$9$d;
    wire  [55:0] stages$9$q;
    reg  stages$9$clock;
    reg  [55:0] stages$10$d;
    wire  [55:0] stages$10$q;
    reg  stages$10$clock;
    reg  [55:0] stages$11$d;
    wire  [55:0] stages$11$q;
    reg  stages$11$clock;
    reg  [55:0] stages$12$d;
    wire  [55:0] stages$12$q;
    reg  stages$12$clock;
    reg  [55:0] stages$13$d;
    wire  [55:0] stages$13$q;
    reg  stages$13$clock;
    reg  [55:0] stages$14$d;
    wire  [55:0] stages$14$q;
    reg  stages$14$clock;
    reg  [55:0] stages$15$d;
    wire  [55:0] stages$15$q;
    reg  stages$15$clock;
    reg  [55:0] stages$16$d;
    wire  [55:0] stages$16$q;
    reg  stages$16$clock;
    reg  [55:0] stages$17$d;
    wire  [55:0] stages$17$q;
    reg  stages$17$clock;
    reg  [55:0] stages$18$d;
    wire  [55:0] stages$18$q;
    reg  stages$18$clock;
    reg  [55:0] stages$19$d;
    wire  [55:0] stages$19$q;
    reg  stages$19$clock;
    reg  [55:0] stages$20$d;
    wire  [55:0] stages$20$q;
    reg  stages$20$clock;
    reg  [55:0] stages$21$d;
    wire  [55:0] stages$21$q;
    reg  stages$21$clock;
    reg  [55:0] stages$22$d;
    wire  [55:0] stages$22$q;
    reg  stages$22$clock;
    reg  [55:0] stages$23$d;
    wire  [55:0] stages$23$q;
    reg  stages$23$clock;
    reg  [55:0] stages$24$d;
    wire  [55:0] stages$24$q;
    reg  stages$24$clock;
    reg  [55:0] stages$25$d;
    wire  [55:0] stages$25$q;
    reg  stages$25$clock;
    reg  [55:0] stages$26$d;
    wire  [55:0] stages$26$q;
    reg  stages$26$clock;
    reg  [55:0] stages$27$d;
    wire  [55:0] stages$27$q;
    reg  stages$27$clock;
    
    // Sub module instances
    vector$lanes$0$q_dl$stages$0 stages$0(
        .d(stages$0$d),
        .q(stages$0$q),
        .clock(stages$0$clock)
    );
    vector$lanes$0$q_dl$stages$1 stages$1(
        .d(stages$1$d),
        .q(stages$1$q),
        .clock(stages$1$clock)
    );
    vector$lanes$0$q_dl$stages$2 stages$2(
        .d(stages$2$d),
        .q(stages$2$q),
        .clock(stages$2$clock)
    );
    vector$lanes$0$q_dl$stages$3 stages$3(
        .d(stages$3$d),
        .q(stages$3$q),
        .clock(stages$3$clock)
    );
    vector$lanes$0$q_dl$stages$4 stages$4(
        .d(stages$4$d),
        .q(stages$4$q),
        .clock(stages$4$clock)
    );
    vector$lanes$0$q_dl$stages$5 stages$5(
        .d(stages$5$d),
        .q(stages$5$q),
        .clock(stages$5$clock)
    );
    vector$lanes$0$q_dl$stages$6 stages$6(
        .d(stages$6$d),
        .q(stages$6$q),
        .clock(stages$6$clock)
    );
    vector$lanes$0$q_dl$stages$7 stages$7(
        .d(stages$7$d),
        .q(stages$7$q),
        .clock(stages$7$clock)
    );
    vector$lanes$0$q_dl$stages$8 stages$8(
        .d(stages$8$d),
        .q(stages$8$q),
        .clock(stages$8$clock)
    );
    vector$lanes$0$q_dl$stages$9 stages$9(
        .d(stages$9$d),
        .q(stages$9$q),
        .clock(stages$9$clock)
    );
    vector$lanes$0$q_dl$stages$10 stages$10(
        .d(stages$10$d),
        .q(stages$10$q),
        .clock(stages$10$clock)
    );
    vector$lanes$0$q_dl$stages$11 stages$11(
        .d(stages$11$d),
        .q(stages$11$q),
        .clock(stages$11$clock)
    );
    vector$lanes$0$q_dl$stages$12 stages$12(
        .d(stages$12$d),
        .q(stages$12$q),
        .clock(stages$12$clock)
    );
    vector$lanes$0$q_dl$stages$13 stages$13(
        .d(stages$13$d),
        .q(stages$13$q),
        .clock(stages$13$clock)
    );
    vector$lanes$0$q_dl$stages$14 stages$14(
        .d(stages$14$d),
        .q(stages$14$q),
        .clock(stages$14$clock)
    );
    vector$lanes$0$q_dl$stages$15 stages$15(
        .d(stages$15$d),
        .q(stages$15$q),
        .clock(stages$15$clock)
    );
    vector$lanes$0$q_dl$stages$16 stages$16(
        .d(stages$16$d),
        .q(stages$16$q),
        .clock(stages$16$clock)
    );
    vector$lanes$0$q_dl$stages$17 stages$17(
        .d(stages$17$d),
        .q(stages$17$q),
        .clock(stages$17$clock)
    );
    vector$lanes$0$q_dl$stages$18 stages$18(
        .d(stages$18$d),
        .q(stages$18$q),
        .clock(stages$18$clock)
    );
    vector$lanes$0$q_dl$stages$19 stages$19(
        .d(stages$19$d),
        .q(stages$19$q),
        .clock(stages$19$clock)
    );
    vector$lanes$0$q_dl$stages$20 stages$20(
        .d(stages$20$d),
        .q(stages$20$q),
        .clock(stages$20$clock)
    );
    vector$lanes$0$q_dl$stages$21 stages$21(
        .d(stages$21$d),
        .q(stages$21$q),
        .clock(stages$21$clock)
    );
    vector$lanes$0$q_dl$stages$22 stages$22(
        .d(stages$22$d),
        .q(stages$22$q),
        .clock(stages$22$clock)
    );
    vector$lanes$0$q_dl$stages$23 stages$23(
        .d(stages$23$d),
        .q(stages$23$q),
        .clock(stages$23$clock)
    );
    vector$lanes$0$q_dl$stages$24 stages$24(
        .d(stages$24$d),
        .q(stages$24$q),
        .clock(stages$24$clock)
    );
    vector$lanes$0$q_dl$stages$25 stages$25(
        .d(stages$25$d),
        .q(stages$25$q),
        .clock(stages$25$clock)
    );
    vector$lanes$0$q_dl$stages$26 stages$26(
        .d(stages$26$d),
        .q(stages$26$q),
        .clock(stages$26$clock)
    );
    vector$lanes$0$q_dl$stages$27 stages$27(
        .d(stages$27$d),
        .q(stages$27$q),
        .clock(stages$27$clock)
    );
    
    // Update code
    always @(*) begin
        stages$0$clock = clock;
        stages$0$d = stages$0$q;
        stages$1$clock = clock;
        stages$1$d = stages$1$q;
        stages$2$clock = clock;
        stages$2$d = stages$2$q;
        stages$3$clock = clock;
        stages$3$d = stages$3$q;
        stages$4$clock = clock;
        stages$4$d = stages$4$q;
        stages$5$clock = clock;
        stages$5$d = stages$5$q;
        stages$6$clock = clock;
        stages$6$d = stages$6$q;
        stages$7$clock = clock;
        stages$7$d = stages$7$q;
        stages$8$clock = clock;
        stages$8$d = stages$8$q;
        stages$9$clock = clock;
        stages$9$d = stages$9$q;
        stages$10$clock = clock;
        stages$10$d = stages$10$q;
        stages$11$clock = clock;
        stages$11$d = stages$11$q;
        stages$12$clock = clock;
        stages$12$d = stages$12$q;
        stages$13$clock = clock;
        stages$13$d = stages$13$q;
        stages$14$clock = clock;
        stages$14$d = stages$14$q;
        stages$15$clock = clock;
        stages$15$d = stages$15$q;
        stages$16$clock = clock;
        stages$16$d = stages$16$q;
        stages$17$clock = clock;
        stages$17$d = stages$17$q;
        stages$18$clock = clock;
        stages$18$d = stages$18$q;
        stages$19$clock = clock;
        stages$19$d = stages$19$q;
        stages$20$clock = clock;
        stages$20$d = stages$20$q;
        stages$21$clock = clock;
        stages$21$d = stages$21$q;
        stages$22$clock = clock;
        stages$22$d = stages$22$q;
        stages$23$clock = clock;
        stages$23$d = stages$23$q;
        stages$24$clock = clock;
        stages$24$d = stages$24$q;
        stages$25$clock = clock;
        stages$25$d = stages$25$q;
        stages$26$clock = clock;
        stages$26$d = stages$26$q;
        stages$27$clock = clock;
        stages$27$d = stages$27$q;
        if (en) begin
            stages$0$d = d;
            stages$1$d = stages$0$q;
            stages$2$d = stages$1$q;
            stages$3$d = stages$2$q;
            stages$4$d = stages$3$q;
            stages$5$d = stages$4$q;
            stages$6$d = stages$5$q;
            stages$7$d = stages$6$q;
            stages$8$d = stages$7$q;
            stages$9$d = stages$8$q;
            stages$10$d = stages$9$q;
            stages$11$d = stages$10$q;
            stages$12$d = stages$11$q;
            stages$13$d = stages$12$q;
            stages$14$d = stages$13$q;
            stages$15$d = stages$14$q;
            stages$16$d = stages$15$q;
            stages$17$d = stages$16$q;
            stages$18$d = stages$17$q;
            stages$19$d = stages$18$q;
            stages$20$d = stages$19$q;
            stages$21$d = stages$20$q;
            stages$22$d = stages$21$q;
            stages$23$d = stages$22$q;
            stages$24$d = stages$23$q;
            stages$25$d = stages$24$q;
            stages$26$d = stages$25$q;
            stages$27$d = stages$26$q;
        end
        q = stages$27$q;
    end
    
endmodule // vector$lanes$0$q_dl


module vector$lanes$0$q_dl$stages$0(d,q,clock);
    
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
          
endmodule // vector$lanes$0$q_dl$stages$0


module vector$lanes$0$q_dl$stages$1(d,q,clock);
    
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
          
endmodule // vector$lanes$0$q_dl$stages$1


module vector$lanes$0$q_dl$stages$10(d,q,clock);
    
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
          
endmodule // vector$lanes$0$q_dl$stages$10


module vector$lanes$0$q_dl$stages$11(d,q,clock);
    
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
          
endmodule // vector$lanes$0$q_dl$stages$11


module vector$lanes$0$q_dl$stages$12(d,q,clock);
    
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
          
endmodule // vector$lanes$0$q_dl$stages$12


module vector$lanes$0$q_dl$stages$13(d,q,clock);
    
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
          
endmodule // vector$lanes$0$q_dl$stages$13


module vector$lanes$0$q_dl$stages$14(d,q,clock);
    
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
          
endmodule // vector$lanes$0$q_dl$stages$14


module vector$lanes$0$q_dl$stages$15(d,q,clock);
    
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
          
endmodule // vector$lanes$0$q_dl$stages$15


module vector$lanes$0$q_dl$stages$16(d,q,clock);
    
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
          
endmodule // vector$lanes$0$q_dl$stages$16


module vector$lanes$0$q_dl$stages$17(d,q,clock);
    
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
          
endmodule // vector$lanes$0$q_dl$stages$17


module vector$lanes$0$q_dl$stages$18(d,q,clock);
    
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
          
endmodule // vector$lanes$0$q_dl$stages$18


module vector$lanes$0$q_dl$stages$19(d,q,clock);
    
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
          
endmodule // vector$lanes$0$q_dl$stages$19


module vector$lanes$0$q_dl$stages$2(d,q,clock);
    
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
          
endmodule // vector$lanes$0$q_dl$stages$2


module vector$lanes$0$q_dl$stages$20(d,q,clock);
    
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
          
endmodule // vector$lanes$0$q_dl$stages$20


module vector$lanes$0$q_dl$stages$21(d,q,clock);
    
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
          
endmodule // vector$lanes$0$q_dl$stages$21


module vector$lanes$0$q_dl$stages$22(d,q,clock);
    
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
          
endmodule // vector$lanes$0$q_dl$stages$22


module vector$lanes$0$q_dl$stages$23(d,q,clock);
    
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
          
endmodule // vector$lanes$0$q_dl$stages$23


module vector$lanes$0$q_dl$stages$24(d,q,clock);
    
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
          
endmodule // vector$lanes$0$q_dl$stages$24


module vector$lanes$0$q_dl$stages$25(d,q,clock);
    
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
          
endmodule // vector$lanes$0$q_dl$stages$25


module vector$lanes$0$q_dl$stages$26(d,q,clock);
    
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
          
endmodule // vector$lanes$0$q_dl$stages$26


module vector$lanes$0$q_dl$stages$27(d,q,clock);
    
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
          
endmodule // vector$lanes$0$q_dl$stages$27


module vector$lanes$0$q_dl$stages$3(d,q,clock);
    
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
          
endmodule // vector$lanes$0$q_dl$stages$3


module vector$lanes$0$q_dl$stages$4(d,q,clock);
    
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
          
endmodule // vector$lanes$0$q_dl$stages$4


module vector$lanes$0$q_dl$stages$5(d,q,clock);
    
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
          
endmodule // vector$lanes$0$q_dl$stages$5


module vector$lanes$0$q_dl$stages$6(d,q,clock);
    
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
          
endmodule // vector$lanes$0$q_dl$stages$6


module vector$lanes$0$q_dl$stages$7(d,q,clock);
    
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
          
endmodule // vector$lanes$0$q_dl$stages$7


module vector$lanes$0$q_dl$stages$8(d,q,clock);
    
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
          
endmodule // vector$lanes$0$q_dl$stages$8


module vector$lanes$0$q_dl$stages$9(d,q,clock);
    
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
          
endmodule // vector$lanes$0$q_dl$stages$9


module vector$lanes$0$rej$0(e,owns,rejects);
    
    // Module arguments
    input wire  [34:0] e;
    input wire  owns;
    output reg  rejects;
    
    // Stub signals
    reg  [34:0] sign$x;
    wire  sign$neg;
    
    // Sub module instances
    vector$lanes$0$rej$0$sign sign(
        .x(sign$x),
        .neg(sign$neg)
    );
    
    // Update code
    always @(*) begin
        sign$x = e;
        rejects = sign$neg | ((e == 32'h0) & ~owns);
    end
    
endmodule // vector$lanes$0$rej$0


module vector$lanes$0$rej$0$sign(x,neg);
    
    // Module arguments
    input wire  [34:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 35'h400000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // vector$lanes$0$rej$0$sign


module vector$lanes$0$rej$1(e,owns,rejects);
    
    // Module arguments
    input wire  [34:0] e;
    input wire  owns;
    output reg  rejects;
    
    // Stub signals
    reg  [34:0] sign$x;
    wire  sign$neg;
    
    // Sub module instances
    vector$lanes$0$rej$1$sign sign(
        .x(sign$x),
        .neg(sign$neg)
    );
    
    // Update code
    always @(*) begin
        sign$x = e;
        rejects = sign$neg | ((e == 32'h0) & ~owns);
    end
    
endmodule // vector$lanes$0$rej$1


module vector$lanes$0$rej$1$sign(x,neg);
    
    // Module arguments
    input wire  [34:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 35'h400000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // vector$lanes$0$rej$1$sign


module vector$lanes$0$rej$2(e,owns,rejects);
    
    // Module arguments
    input wire  [34:0] e;
    input wire  owns;
    output reg  rejects;
    
    // Stub signals
    reg  [34:0] sign$x;
    wire  sign$neg;
    
    // Sub module instances
    vector$lanes$0$rej$2$sign sign(
        .x(sign$x),
        .neg(sign$neg)
    );
    
    // Update code
    always @(*) begin
        sign$x = e;
        rejects = sign$neg | ((e == 32'h0) & ~owns);
    end
    
endmodule // vector$lanes$0$rej$2


module vector$lanes$0$rej$2$sign(x,neg);
    
    // Module arguments
    input wire  [34:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 35'h400000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // vector$lanes$0$rej$2$sign


module vector$lanes$0$rs_a(x,by,y);
    
    // Module arguments
    input wire  [60:0] x;
    input wire  [7:0] by;
    output reg  [27:0] y;
    
    // Constant declarations
    localparam  lsh = 8'h2;
    localparam  rsh = 8'h0;
    localparam  msb = 8'h3c;
    localparam  ext = 61'h0;
    
    // Local signals
    reg  [60:0] wide;
    reg  [60:0] shifted;
    
    // Update code
    always @(*) begin
        wide = ((x) & 61'h1fffffffffffffff);
        if (x[msb]) begin
            wide = ((x) & 61'h1fffffffffffffff) | ext;
        end
        shifted = ((wide << lsh) >> rsh) >> by;
        y = ((shifted) & 28'hfffffff);
    end
    
endmodule // vector$lanes$0$rs_a


module vector$lanes$0$rs_b(x,by,y);
    
    // Module arguments
    input wire  [60:0] x;
    input wire  [7:0] by;
    output reg  [27:0] y;
    
    // Constant declarations
    localparam  lsh = 8'h2;
    localparam  rsh = 8'h0;
    localparam  msb = 8'h3c;
    localparam  ext = 61'h0;
    
    // Local signals
    reg  [60:0] wide;
    reg  [60:0] shifted;
    
    // Update code
    always @(*) begin
        wide = ((x) & 61'h1fffffffffffffff);
        if (x[msb]) begin
            wide = ((x) & 61'h1fffffffffffffff) | ext;
        end
        shifted = ((wide << lsh) >> rsh) >> by;
        y = ((shifted) & 28'hfffffff);
    end
    
endmodule // vector$lanes$0$rs_b


module vector$lanes$0$rs_c$0(x,by,y);
    
    // Module arguments
    input wire  [37:0] x;
    input wire  [7:0] by;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  lsh = 8'h0;
    localparam  rsh = 8'h4;
    localparam  msb = 8'h25;
    localparam  ext = 38'h0;
    
    // Local signals
    reg  [37:0] wide;
    reg  [37:0] shifted;
    
    // Update code
    always @(*) begin
        wide = ((x) & 38'h3fffffffff);
        if (x[msb]) begin
            wide = ((x) & 38'h3fffffffff) | ext;
        end
        shifted = ((wide << lsh) >> rsh) >> by;
        y = ((shifted) & 32'hffffffff);
    end
    
endmodule // vector$lanes$0$rs_c$0


module vector$lanes$0$rs_c$1(x,by,y);
    
    // Module arguments
    input wire  [37:0] x;
    input wire  [7:0] by;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  lsh = 8'h0;
    localparam  rsh = 8'h4;
    localparam  msb = 8'h25;
    localparam  ext = 38'h0;
    
    // Local signals
    reg  [37:0] wide;
    reg  [37:0] shifted;
    
    // Update code
    always @(*) begin
        wide = ((x) & 38'h3fffffffff);
        if (x[msb]) begin
            wide = ((x) & 38'h3fffffffff) | ext;
        end
        shifted = ((wide << lsh) >> rsh) >> by;
        y = ((shifted) & 32'hffffffff);
    end
    
endmodule // vector$lanes$0$rs_c$1


module vector$lanes$0$rs_c$2(x,by,y);
    
    // Module arguments
    input wire  [37:0] x;
    input wire  [7:0] by;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  lsh = 8'h0;
    localparam  rsh = 8'h4;
    localparam  msb = 8'h25;
    localparam  ext = 38'h0;
    
    // Local signals
    reg  [37:0] wide;
    reg  [37:0] shifted;
    
    // Update code
    always @(*) begin
        wide = ((x) & 38'h3fffffffff);
        if (x[msb]) begin
            wide = ((x) & 38'h3fffffffff) | ext;
        end
        shifted = ((wide << lsh) >> rsh) >> by;
        y = ((shifted) & 32'hffffffff);
    end
    
endmodule // vector$lanes$0$rs_c$2


module vector$lanes$0$rs_c0$0(x,by,y);
    
    // Module arguments
    input wire  [8:0] x;
    input wire  [7:0] by;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  lsh = 8'h16;
    localparam  rsh = 8'h0;
    localparam  msb = 8'h8;
    localparam  ext = 32'hfffffe00;
    
    // Local signals
    reg  [31:0] wide;
    reg  [31:0] shifted;
    
    // Update code
    always @(*) begin
        wide = ((x) & 32'hffffffff);
        if (x[msb]) begin
            wide = ((x) & 32'hffffffff) | ext;
        end
        shifted = ((wide << lsh) >> rsh) >> by;
        y = ((shifted) & 32'hffffffff);
    end
    
endmodule // vector$lanes$0$rs_c0$0


module vector$lanes$0$rs_c0$1(x,by,y);
    
    // Module arguments
    input wire  [8:0] x;
    input wire  [7:0] by;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  lsh = 8'h16;
    localparam  rsh = 8'h0;
    localparam  msb = 8'h8;
    localparam  ext = 32'hfffffe00;
    
    // Local signals
    reg  [31:0] wide;
    reg  [31:0] shifted;
    
    // Update code
    always @(*) begin
        wide = ((x) & 32'hffffffff);
        if (x[msb]) begin
            wide = ((x) & 32'hffffffff) | ext;
        end
        shifted = ((wide << lsh) >> rsh) >> by;
        y = ((shifted) & 32'hffffffff);
    end
    
endmodule // vector$lanes$0$rs_c0$1


module vector$lanes$0$rs_c0$2(x,by,y);
    
    // Module arguments
    input wire  [8:0] x;
    input wire  [7:0] by;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  lsh = 8'h16;
    localparam  rsh = 8'h0;
    localparam  msb = 8'h8;
    localparam  ext = 32'hfffffe00;
    
    // Local signals
    reg  [31:0] wide;
    reg  [31:0] shifted;
    
    // Update code
    always @(*) begin
        wide = ((x) & 32'hffffffff);
        if (x[msb]) begin
            wide = ((x) & 32'hffffffff) | ext;
        end
        shifted = ((wide << lsh) >> rsh) >> by;
        y = ((shifted) & 32'hffffffff);
    end
    
endmodule // vector$lanes$0$rs_c0$2


module vector$lanes$0$rs_q$0(x,by,y);
    
    // Module arguments
    input wire  [44:0] x;
    input wire  [7:0] by;
    output reg  [27:0] y;
    
    // Constant declarations
    localparam  lsh = 8'h0;
    localparam  rsh = 8'hf;
    localparam  msb = 8'h2c;
    localparam  ext = 45'h0;
    
    // Local signals
    reg  [44:0] wide;
    reg  [44:0] shifted;
    
    // Update code
    always @(*) begin
        wide = ((x) & 45'h1fffffffffff);
        if (x[msb]) begin
            wide = ((x) & 45'h1fffffffffff) | ext;
        end
        shifted = ((wide << lsh) >> rsh) >> by;
        y = ((shifted) & 28'hfffffff);
    end
    
endmodule // vector$lanes$0$rs_q$0


module vector$lanes$0$rs_q$1(x,by,y);
    
    // Module arguments
    input wire  [44:0] x;
    input wire  [7:0] by;
    output reg  [27:0] y;
    
    // Constant declarations
    localparam  lsh = 8'h0;
    localparam  rsh = 8'hf;
    localparam  msb = 8'h2c;
    localparam  ext = 45'h0;
    
    // Local signals
    reg  [44:0] wide;
    reg  [44:0] shifted;
    
    // Update code
    always @(*) begin
        wide = ((x) & 45'h1fffffffffff);
        if (x[msb]) begin
            wide = ((x) & 45'h1fffffffffff) | ext;
        end
        shifted = ((wide << lsh) >> rsh) >> by;
        y = ((shifted) & 28'hfffffff);
    end
    
endmodule // vector$lanes$0$rs_q$1


module vector$lanes$0$rs_q$2(x,by,y);
    
    // Module arguments
    input wire  [44:0] x;
    input wire  [7:0] by;
    output reg  [27:0] y;
    
    // Constant declarations
    localparam  lsh = 8'h0;
    localparam  rsh = 8'hf;
    localparam  msb = 8'h2c;
    localparam  ext = 45'h0;
    
    // Local signals
    reg  [44:0] wide;
    reg  [44:0] shifted;
    
    // Update code
    always @(*) begin
        wide = ((x) & 45'h1fffffffffff);
        if (x[msb]) begin
            wide = ((x) & 45'h1fffffffffff) | ext;
        end
        shifted = ((wide << lsh) >> rsh) >> by;
        y = ((shifted) & 28'hfffffff);
    end
    
endmodule // vector$lanes$0$rs_q$2


module vector$lanes$0$rs_ra(x,by,y);
    
    // Module arguments
    input wire  [53:0] x;
    input wire  [7:0] by;
    output reg  [27:0] y;
    
    // Constant declarations
    localparam  lsh = 8'h2;
    localparam  rsh = 8'h0;
    localparam  msb = 8'h35;
    localparam  ext = 58'h3c0000000000000;
    
    // Local signals
    reg  [57:0] wide;
    reg  [57:0] shifted;
    
    // Update code
    always @(*) begin
        wide = ((x) & 58'h3ffffffffffffff);
        if (x[msb]) begin
            wide = ((x) & 58'h3ffffffffffffff) | ext;
        end
        shifted = ((wide << lsh) >> rsh) >> by;
        y = ((shifted) & 28'hfffffff);
    end
    
endmodule // vector$lanes$0$rs_ra


module vector$lanes$0$rs_rb(x,by,y);
    
    // Module arguments
    input wire  [53:0] x;
    input wire  [7:0] by;
    output reg  [27:0] y;
    
    // Constant declarations
    localparam  lsh = 8'h2;
    localparam  rsh = 8'h0;
    localparam  msb = 8'h35;
    localparam  ext = 58'h3c0000000000000;
    
    // Local signals
    reg  [57:0] wide;
    reg  [57:0] shifted;
    
    // Update code
    always @(*) begin
        wide = ((x) & 58'h3ffffffffffffff);
        if (x[msb]) begin
            wide = ((x) & 58'h3ffffffffffffff) | ext;
        end
        shifted = ((wide << lsh) >> rsh) >> by;
        y = ((shifted) & 28'hfffffff);
    end
    
endmodule // vector$lanes$0$rs_rb


module vector$lanes$0$rs_z(x,by,y);
    
    // Module arguments
    input wire  [47:0] x;
    input wire  [7:0] by;
    output reg  [35:0] y;
    
    // Constant declarations
    localparam  lsh = 8'h0;
    localparam  rsh = 8'h8;
    localparam  msb = 8'h2f;
    localparam  ext = 48'h0;
    
    // Local signals
    reg  [47:0] wide;
    reg  [47:0] shifted;
    
    // Update code
    always @(*) begin
        wide = ((x) & 48'hffffffffffff);
        if (x[msb]) begin
            wide = ((x) & 48'hffffffffffff) | ext;
        end
        shifted = ((wide << lsh) >> rsh) >> by;
        y = ((shifted) & 36'hfffffffff);
    end
    
endmodule // vector$lanes$0$rs_z


module vector$lanes$0$rs_z0(x,by,y);
    
    // Module arguments
    input wire  [18:0] x;
    input wire  [7:0] by;
    output reg  [35:0] y;
    
    // Constant declarations
    localparam  lsh = 8'h12;
    localparam  rsh = 8'h0;
    localparam  msb = 8'h12;
    localparam  ext = 36'hffff80000;
    
    // Local signals
    reg  [35:0] wide;
    reg  [35:0] shifted;
    
    // Update code
    always @(*) begin
        wide = ((x) & 36'hfffffffff);
        if (x[msb]) begin
            wide = ((x) & 36'hfffffffff) | ext;
        end
        shifted = ((wide << lsh) >> rsh) >> by;
        y = ((shifted) & 36'hfffffffff);
    end
    
endmodule // vector$lanes$0$rs_z0


module vector$lanes$0$sum7(d,q,clock);
    
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
          
endmodule // vector$lanes$0$sum7


module vector$lanes$0$sum8(d,q,clock);
    
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
          
endmodule // vector$lanes$0$sum8


module vector$lanes$0$z6(d,q,clock);
    
    // Module arguments
    input wire  [35:0] d;
    output reg  [35:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 36'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$lanes$0$z6


module vector$lead_a(x,pos);
    
    // Module arguments
    input wire  [33:0] x;
    output reg  [7:0] pos;
    
    // Constant declarations
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
    
    // Update code
    always @(*) begin
        pos = 32'h0;
        if (x[0]) begin
            pos = index$0;
        end
        if (x[1]) begin
            pos = index$1;
        end
        if (x[2]) begin
            pos = index$2;
        end
        if (x[3]) begin
            pos = index$3;
        end
        if (x[4]) begin
            pos = index$4;
        end
        if (x[5]) begin
            pos = index$5;
        end
        if (x[6]) begin
            pos = index$6;
        end
        if (x[7]) begin
            pos = index$7;
        end
        if (x[8]) begin
            pos = index$8;
        end
        if (x[9]) begin
            pos = index$9;
        end
        if (x[10]) begin
            pos = index$10;
        end
        if (x[11]) begin
            pos = index$11;
        end
        if (x[12]) begin
            pos = index$12;
        end
        if (x[13]) begin
            pos = index$13;
        end
        if (x[14]) begin
            pos = index$14;
        end
        if (x[15]) begin
            pos = index$15;
        end
        if (x[16]) begin
            pos = index$16;
        end
        if (x[17]) begin
            pos = index$17;
        end
        if (x[18]) begin
            pos = index$18;
        end
        if (x[19]) begin
            pos = index$19;
        end
        if (x[20]) begin
            pos = index$20;
        end
        if (x[21]) begin
            pos = index$21;
        end
        if (x[22]) begin
            pos = index$22;
        end
        if (x[23]) begin
            pos = index$23;
        end
        if (x[24]) begin
            pos = index$24;
        end
        if (x[25]) begin
            pos = index$25;
        end
        if (x[26]) begin
            pos = index$26;
        end
        if (x[27]) begin
            pos = index$27;
        end
        if (x[28]) begin
            pos = index$28;
        end
        if (x[29]) begin
            pos = index$29;
        end
        if (x[30]) begin
            pos = index$30;
        end
        if (x[31]) begin
            pos = index$31;
        end
        if (x[32]) begin
            pos = index$32;
        end
        if (x[33]) begin
            pos = index$33;
        end
    end
    
endmodule // vector$lead_a


module vector$mant(d,q,clock);
    
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
          
endmodule // vector$mant


module vector$max_xr(d,q,clock);
    
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
          
endmodule // vector$max_xr


module vector$max_yr(d,q,clock);
    
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
          
endmodule // vector$max_yr


module vector$min_xr(d,q,clock);
    
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
          
endmodule // vector$min_xr


module vector$min_yr(d,q,clock);
    
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
          
endmodule // vector$min_yr


module vector$mul_s$0(clock,en,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  en;
    input wire  [16:0] a;
    input wire  [16:0] b;
    output reg  [34:0] p;
    
    // Stub signals
    reg  [16:0] a_r$d;
    wire  [16:0] a_r$q;
    reg  a_r$clock;
    reg  [16:0] b_r$d;
    wire  [16:0] b_r$q;
    reg  b_r$clock;
    reg  [34:0] p_r$d;
    wire  [34:0] p_r$q;
    reg  p_r$clock;
    reg  [16:0] mul$a;
    reg  [16:0] mul$b;
    wire  [34:0] mul$p;
    
    // Sub module instances
    vector$mul_s$0$a_r a_r(
        .d(a_r$d),
        .q(a_r$q),
        .clock(a_r$clock)
    );
    vector$mul_s$0$b_r b_r(
        .d(b_r$d),
        .q(b_r$q),
        .clock(b_r$clock)
    );
    vector$mul_s$0$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$mul_s$0$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        a_r$clock = clock;
        b_r$clock = clock;
        p_r$clock = clock;
        a_r$d = a_r$q;
        b_r$d = b_r$q;
        p_r$d = p_r$q;
        mul$a = a_r$q;
        mul$b = b_r$q;
        if (en) begin
            a_r$d = a;
            b_r$d = b;
            p_r$d = mul$p;
        end
        p = p_r$q;
    end
    
endmodule // vector$mul_s$0


module vector$mul_s$0$a_r(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$mul_s$0$a_r


module vector$mul_s$0$b_r(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$mul_s$0$b_r


module vector$mul_s$0$mul(a,b,p);
    
    // Module arguments
    input wire  [16:0] a;
    input wire  [16:0] b;
    output reg  [34:0] p;
    
    // Update code (custom)
    // p = low 35 bits of a * b, both signed: a signed 35-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // vector$mul_s$0$mul


module vector$mul_s$0$p_r(d,q,clock);
    
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
          
endmodule // vector$mul_s$0$p_r


module vector$mul_s$1(clock,en,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  en;
    input wire  [16:0] a;
    input wire  [16:0] b;
    output reg  [34:0] p;
    
    // Stub signals
    reg  [16:0] a_r$d;
    wire  [16:0] a_r$q;
    reg  a_r$clock;
    reg  [16:0] b_r$d;
    wire  [16:0] b_r$q;
    reg  b_r$clock;
    reg  [34:0] p_r$d;
    wire  [34:0] p_r$q;
    reg  p_r$clock;
    reg  [16:0] mul$a;
    reg  [16:0] mul$b;
    wire  [34:0] mul$p;
    
    // Sub module instances
    vector$mul_s$1$a_r a_r(
        .d(a_r$d),
        .q(a_r$q),
        .clock(a_r$clock)
    );
    vector$mul_s$1$b_r b_r(
        .d(b_r$d),
        .q(b_r$q),
        .clock(b_r$clock)
    );
    vector$mul_s$1$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    vector$mul_s$1$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        a_r$clock = clock;
        b_r$clock = clock;
        p_r$clock = clock;
        a_r$d = a_r$q;
        b_r$d = b_r$q;
        p_r$d = p_r$q;
        mul$a = a_r$q;
        mul$b = b_r$q;
        if (en) begin
            a_r$d = a;
            b_r$d = b;
            p_r$d = mul$p;
        end
        p = p_r$q;
    end
    
endmodule // vector$mul_s$1


module vector$mul_s$1$a_r(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$mul_s$1$a_r


module vector$mul_s$1$b_r(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$mul_s$1$b_r


module vector$mul_s$1$mul(a,b,p);
    
    // Module arguments
    input wire  [16:0] a;
    input wire  [16:0] b;
    output reg  [34:0] p;
    
    // Update code (custom)
    // p = low 35 bits of a * b, both signed: a signed 35-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // vector$mul_s$1$mul


module vector$mul_s$1$p_r(d,q,clock);
    
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
          
endmodule // vector$mul_s$1$p_r


module vector$neg_hi_x(x,neg);
    
    // Module arguments
    input wire  [16:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 17'b10000000000000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // vector$neg_hi_x


module vector$neg_hi_y(x,neg);
    
    // Module arguments
    input wire  [16:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 17'b10000000000000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // vector$neg_hi_y


module vector$neg_lo_x(x,neg);
    
    // Module arguments
    input wire  [16:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 17'b10000000000000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // vector$neg_lo_x


module vector$neg_lo_y(x,neg);
    
    // Module arguments
    input wire  [16:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 17'b10000000000000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // vector$neg_lo_y


module vector$neg_top(x,neg);
    
    // Module arguments
    input wire  [15:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 16'h8000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // vector$neg_top


module vector$norm_a(x,exp,d);
    
    // Module arguments
    input wire  [33:0] x;
    input wire  [7:0] exp;
    output reg  [33:0] d;
    
    // Constant declarations
    localparam  top = 8'h20;
    
    // Local signals
    reg  [7:0] lsh;
    reg  [7:0] rsh;
    reg  [34:0] wide;
    
    // Update code
    always @(*) begin
        lsh = top - exp;
        rsh = 32'h0;
        if (exp > top) begin
            lsh = 32'h0;
            rsh = exp - top;
        end
        wide = (((x) & 35'h7ffffffff) << lsh) >> rsh;
        d = ((wide) & 34'h3ffffffff);
    end
    
endmodule // vector$norm_a


module vector$o_x(d,q,clock);
    
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
          
endmodule // vector$o_x


module vector$o_y(d,q,clock);
    
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
          
endmodule // vector$o_y


module vector$ph(d,q,clock);
    
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
          
endmodule // vector$ph


module vector$place_rgb$0(x,y);
    
    // Module arguments
    input wire  [23:0] x;
    output reg  [23:0] y;
    
    // Constant declarations
    localparam  at = 16'h0;
    
    // Update code
    always @(*) begin
        y = ((x) & 24'hffffff) << at;
    end
    
endmodule // vector$place_rgb$0


module vector$place_z$0(x,y);
    
    // Module arguments
    input wire  [15:0] x;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  at = 16'h0;
    
    // Update code
    always @(*) begin
        y = ((x) & 16'hffff) << at;
    end
    
endmodule // vector$place_z$0


module vector$rej_lf$0(e,owns,rejects);
    
    // Module arguments
    input wire  [34:0] e;
    input wire  owns;
    output reg  rejects;
    
    // Stub signals
    reg  [34:0] sign$x;
    wire  sign$neg;
    
    // Sub module instances
    vector$rej_lf$0$sign sign(
        .x(sign$x),
        .neg(sign$neg)
    );
    
    // Update code
    always @(*) begin
        sign$x = e;
        rejects = sign$neg | ((e == 32'h0) & ~owns);
    end
    
endmodule // vector$rej_lf$0


module vector$rej_lf$0$sign(x,neg);
    
    // Module arguments
    input wire  [34:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 35'h400000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // vector$rej_lf$0$sign


module vector$rej_lf$1(e,owns,rejects);
    
    // Module arguments
    input wire  [34:0] e;
    input wire  owns;
    output reg  rejects;
    
    // Stub signals
    reg  [34:0] sign$x;
    wire  sign$neg;
    
    // Sub module instances
    vector$rej_lf$1$sign sign(
        .x(sign$x),
        .neg(sign$neg)
    );
    
    // Update code
    always @(*) begin
        sign$x = e;
        rejects = sign$neg | ((e == 32'h0) & ~owns);
    end
    
endmodule // vector$rej_lf$1


module vector$rej_lf$1$sign(x,neg);
    
    // Module arguments
    input wire  [34:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 35'h400000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // vector$rej_lf$1$sign


module vector$rej_lf$2(e,owns,rejects);
    
    // Module arguments
    input wire  [34:0] e;
    input wire  owns;
    output reg  rejects;
    
    // Stub signals
    reg  [34:0] sign$x;
    wire  sign$neg;
    
    // Sub module instances
    vector$rej_lf$2$sign sign(
        .x(sign$x),
        .neg(sign$neg)
    );
    
    // Update code
    always @(*) begin
        sign$x = e;
        rejects = sign$neg | ((e == 32'h0) & ~owns);
    end
    
endmodule // vector$rej_lf$2


module vector$rej_lf$2$sign(x,neg);
    
    // Module arguments
    input wire  [34:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 35'h400000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // vector$rej_lf$2$sign


module vector$rej_ll$0(e,owns,rejects);
    
    // Module arguments
    input wire  [34:0] e;
    input wire  owns;
    output reg  rejects;
    
    // Stub signals
    reg  [34:0] sign$x;
    wire  sign$neg;
    
    // Sub module instances
    vector$rej_ll$0$sign sign(
        .x(sign$x),
        .neg(sign$neg)
    );
    
    // Update code
    always @(*) begin
        sign$x = e;
        rejects = sign$neg | ((e == 32'h0) & ~owns);
    end
    
endmodule // vector$rej_ll$0


module vector$rej_ll$0$sign(x,neg);
    
    // Module arguments
    input wire  [34:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 35'h400000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // vector$rej_ll$0$sign


module vector$rej_ll$1(e,owns,rejects);
    
    // Module arguments
    input wire  [34:0] e;
    input wire  owns;
    output reg  rejects;
    
    // Stub signals
    reg  [34:0] sign$x;
    wire  sign$neg;
    
    // Sub module instances
    vector$rej_ll$1$sign sign(
        .x(sign$x),
        .neg(sign$neg)
    );
    
    // Update code
    always @(*) begin
        sign$x = e;
        rejects = sign$neg | ((e == 32'h0) & ~owns);
    end
    
endmodule // vector$rej_ll$1


module vector$rej_ll$1$sign(x,neg);
    
    // Module arguments
    input wire  [34:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 35'h400000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // vector$rej_ll$1$sign


module vector$rej_ll$2(e,owns,rejects);
    
    // Module arguments
    input wire  [34:0] e;
    input wire  owns;
    output reg  rejects;
    
    // Stub signals
    reg  [34:0] sign$x;
    wire  sign$neg;
    
    // Sub module instances
    vector$rej_ll$2$sign sign(
        .x(sign$x),
        .neg(sign$neg)
    );
    
    // Update code
    always @(*) begin
        sign$x = e;
        rejects = sign$neg | ((e == 32'h0) & ~owns);
    end
    
endmodule // vector$rej_ll$2


module vector$rej_ll$2$sign(x,neg);
    
    // Module arguments
    input wire  [34:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 35'h400000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // vector$rej_ll$2$sign


module vector$rej_lm$0(e,owns,rejects);
    
    // Module arguments
    input wire  [34:0] e;
    input wire  owns;
    output reg  rejects;
    
    // Stub signals
    reg  [34:0] sign$x;
    wire  sign$neg;
    
    // Sub module instances
    vector$rej_lm$0$sign sign(
        .x(sign$x),
        .neg(sign$neg)
    );
    
    // Update code
    always @(*) begin
        sign$x = e;
        rejects = sign$neg | ((e == 32'h0) & ~owns);
    end
    
endmodule // vector$rej_lm$0


module vector$rej_lm$0$sign(x,neg);
    
    // Module arguments
    input wire  [34:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 35'h400000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // vector$rej_lm$0$sign


module vector$rej_lm$1(e,owns,rejects);
    
    // Module arguments
    input wire  [34:0] e;
    input wire  owns;
    output reg  rejects;
    
    // Stub signals
    reg  [34:0] sign$x;
    wire  sign$neg;
    
    // Sub module instances
    vector$rej_lm$1$sign sign(
        .x(sign$x),
        .neg(sign$neg)
    );
    
    // Update code
    always @(*) begin
        sign$x = e;
        rejects = sign$neg | ((e == 32'h0) & ~owns);
    end
    
endmodule // vector$rej_lm$1


module vector$rej_lm$1$sign(x,neg);
    
    // Module arguments
    input wire  [34:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 35'h400000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // vector$rej_lm$1$sign


module vector$rej_lm$2(e,owns,rejects);
    
    // Module arguments
    input wire  [34:0] e;
    input wire  owns;
    output reg  rejects;
    
    // Stub signals
    reg  [34:0] sign$x;
    wire  sign$neg;
    
    // Sub module instances
    vector$rej_lm$2$sign sign(
        .x(sign$x),
        .neg(sign$neg)
    );
    
    // Update code
    always @(*) begin
        sign$x = e;
        rejects = sign$neg | ((e == 32'h0) & ~owns);
    end
    
endmodule // vector$rej_lm$2


module vector$rej_lm$2$sign(x,neg);
    
    // Module arguments
    input wire  [34:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 35'h400000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // vector$rej_lm$2$sign


module vector$rej_rf$0(e,owns,rejects);
    
    // Module arguments
    input wire  [34:0] e;
    input wire  owns;
    output reg  rejects;
    
    // Stub signals
    reg  [34:0] sign$x;
    wire  sign$neg;
    
    // Sub module instances
    vector$rej_rf$0$sign sign(
        .x(sign$x),
        .neg(sign$neg)
    );
    
    // Update code
    always @(*) begin
        sign$x = e;
        rejects = sign$neg | ((e == 32'h0) & ~owns);
    end
    
endmodule // vector$rej_rf$0


module vector$rej_rf$0$sign(x,neg);
    
    // Module arguments
    input wire  [34:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 35'h400000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // vector$rej_rf$0$sign


module vector$rej_rf$1(e,owns,rejects);
    
    // Module arguments
    input wire  [34:0] e;
    input wire  owns;
    output reg  rejects;
    
    // Stub signals
    reg  [34:0] sign$x;
    wire  sign$neg;
    
    // Sub module instances
    vector$rej_rf$1$sign sign(
        .x(sign$x),
        .neg(sign$neg)
    );
    
    // Update code
    always @(*) begin
        sign$x = e;
        rejects = sign$neg | ((e == 32'h0) & ~owns);
    end
    
endmodule // vector$rej_rf$1


module vector$rej_rf$1$sign(x,neg);
    
    // Module arguments
    input wire  [34:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 35'h400000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // vector$rej_rf$1$sign


module vector$rej_rf$2(e,owns,rejects);
    
    // Module arguments
    input wire  [34:0] e;
    input wire  owns;
    output reg  rejects;
    
    // Stub signals
    reg  [34:0] sign$x;
    wire  sign$neg;
    
    // Sub module instances
    vector$rej_rf$2$sign sign(
        .x(sign$x),
        .neg(sign$neg)
    );
    
    // Update code
    always @(*) begin
        sign$x = e;
        rejects = sign$neg | ((e == 32'h0) & ~owns);
    end
    
endmodule // vector$rej_rf$2


module vector$rej_rf$2$sign(x,neg);
    
    // Module arguments
    input wire  [34:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 35'h400000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // vector$rej_rf$2$sign


module vector$rej_rn$0(e,owns,rejects);
    
    // Module arguments
    input wire  [34:0] e;
    input wire  owns;
    output reg  rejects;
    
    // Stub signals
    reg  [34:0] sign$x;
    wire  sign$neg;
    
    // Sub module instances
    vector$rej_rn$0$sign sign(
        .x(sign$x),
        .neg(sign$neg)
    );
    
    // Update code
    always @(*) begin
        sign$x = e;
        rejects = sign$neg | ((e == 32'h0) & ~owns);
    end
    
endmodule // vector$rej_rn$0


module vector$rej_rn$0$sign(x,neg);
    
    // Module arguments
    input wire  [34:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 35'h400000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // vector$rej_rn$0$sign


module vector$rej_rn$1(e,owns,rejects);
    
    // Module arguments
    input wire  [34:0] e;
    input wire  owns;
    output reg  rejects;
    
    // Stub signals
    reg  [34:0] sign$x;
    wire  sign$neg;
    
    // Sub module instances
    vector$rej_rn$1$sign sign(
        .x(sign$x),
        .neg(sign$neg)
    );
    
    // Update code
    always @(*) begin
        sign$x = e;
        rejects = sign$neg | ((e == 32'h0) & ~owns);
    end
    
endmodule // vector$rej_rn$1


module vector$rej_rn$1$sign(x,neg);
    
    // Module arguments
    input wire  [34:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 35'h400000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // vector$rej_rn$1$sign


module vector$rej_rn$2(e,owns,rejects);
    
    // Module arguments
    input wire  [34:0] e;
    input wire  owns;
    output reg  rejects;
    
    // Stub signals
    reg  [34:0] sign$x;
    wire  sign$neg;
    
    // Sub module instances
    vector$rej_rn$2$sign sign(
        .x(sign$x),
        .neg(sign$neg)
    );
    
    // Update code
    always @(*) begin
        sign$x = e;
        rejects = sign$neg | ((e == 32'h0) & ~owns);
    end
    
endmodule // vector$rej_rn$2


module vector$rej_rn$2$sign(x,neg);
    
    // Module arguments
    input wire  [34:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 35'h400000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // vector$rej_rn$2$sign


module vector$sbusy(d,q,clock);
    
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
          
endmodule // vector$sbusy


module vector$sc(d,q,clock);
    
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
          
endmodule // vector$sc


module vector$sc0(d,q,clock);
    
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
          
endmodule // vector$sc0


module vector$sc1(d,q,clock);
    
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
          
endmodule // vector$sc1


module vector$scls$0(dx,dy,left,right,flat,owns,g,h);
    
    // Module arguments
    input wire  [16:0] dx;
    input wire  [16:0] dy;
    output reg  left;
    output reg  right;
    output reg  flat;
    output reg  owns;
    output reg  [34:0] g;
    output reg  [34:0] h;
    
    // Constant declarations
    localparam  frac = 8'h4;
    
    // Stub signals
    reg  [16:0] dx_neg$x;
    wire  dx_neg$neg;
    reg  [16:0] dy_neg$x;
    wire  dy_neg$neg;
    reg  [16:0] ex$x;
    wire  [34:0] ex$y;
    reg  [16:0] ey$x;
    wire  [34:0] ey$y;
    
    // Sub module instances
    vector$scls$0$dx_neg dx_neg(
        .x(dx_neg$x),
        .neg(dx_neg$neg)
    );
    vector$scls$0$dy_neg dy_neg(
        .x(dy_neg$x),
        .neg(dy_neg$neg)
    );
    vector$scls$0$ex ex(
        .x(ex$x),
        .y(ex$y)
    );
    vector$scls$0$ey ey(
        .x(ey$x),
        .y(ey$y)
    );
    
    // Update code
    always @(*) begin
        dx_neg$x = dx;
        dy_neg$x = dy;
        left = dy_neg$neg;
        flat = dy == 32'h0;
        right = ~dy_neg$neg & (dy != 32'h0);
        owns = dy_neg$neg | ((dy == 32'h0) & ~dx_neg$neg & (dx != 32'h0));
        ex$x = dx;
        ey$x = dy;
        g = ey$y << frac;
        h = ex$y << frac;
    end
    
endmodule // vector$scls$0


module vector$scls$0$dx_neg(x,neg);
    
    // Module arguments
    input wire  [16:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 17'b10000000000000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // vector$scls$0$dx_neg


module vector$scls$0$dy_neg(x,neg);
    
    // Module arguments
    input wire  [16:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 17'b10000000000000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // vector$scls$0$dy_neg


module vector$scls$0$ex(x,y);
    
    // Module arguments
    input wire  [16:0] x;
    output reg  [34:0] y;
    
    // Constant declarations
    localparam  msb = 8'h10;
    localparam  ext = 35'h7fffe0000;
    
    // Update code
    always @(*) begin
        y = ((x) & 35'h7ffffffff);
        if (x[msb]) begin
            y = ((x) & 35'h7ffffffff) | ext;
        end
    end
    
endmodule // vector$scls$0$ex


module vector$scls$0$ey(x,y);
    
    // Module arguments
    input wire  [16:0] x;
    output reg  [34:0] y;
    
    // Constant declarations
    localparam  msb = 8'h10;
    localparam  ext = 35'h7fffe0000;
    
    // Update code
    always @(*) begin
        y = ((x) & 35'h7ffffffff);
        if (x[msb]) begin
            y = ((x) & 35'h7ffffffff) | ext;
        end
    end
    
endmodule // vector$scls$0$ey


module vector$scls$1(dx,dy,left,right,flat,owns,g,h);
    
    // Module arguments
    input wire  [16:0] dx;
    input wire  [16:0] dy;
    output reg  left;
    output reg  right;
    output reg  flat;
    output reg  owns;
    output reg  [34:0] g;
    output reg  [34:0] h;
    
    // Constant declarations
    localparam  frac = 8'h4;
    
    // Stub signals
    reg  [16:0] dx_neg$x;
    wire  dx_neg$neg;
    reg  [16:0] dy_neg$x;
    wire  dy_neg$neg;
    reg  [16:0] ex$x;
    wire  [34:0] ex$y;
    reg  [16:0] ey$x;
    wire  [34:0] ey$y;
    
    // Sub module instances
    vector$scls$1$dx_neg dx_neg(
        .x(dx_neg$x),
        .neg(dx_neg$neg)
    );
    vector$scls$1$dy_neg dy_neg(
        .x(dy_neg$x),
        .neg(dy_neg$neg)
    );
    vector$scls$1$ex ex(
        .x(ex$x),
        .y(ex$y)
    );
    vector$scls$1$ey ey(
        .x(ey$x),
        .y(ey$y)
    );
    
    // Update code
    always @(*) begin
        dx_neg$x = dx;
        dy_neg$x = dy;
        left = dy_neg$neg;
        flat = dy == 32'h0;
        right = ~dy_neg$neg & (dy != 32'h0);
        owns = dy_neg$neg | ((dy == 32'h0) & ~dx_neg$neg & (dx != 32'h0));
        ex$x = dx;
        ey$x = dy;
        g = ey$y << frac;
        h = ex$y << frac;
    end
    
endmodule // vector$scls$1


module vector$scls$1$dx_neg(x,neg);
    
    // Module arguments
    input wire  [16:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 17'b10000000000000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // vector$scls$1$dx_neg


module vector$scls$1$dy_neg(x,neg);
    
    // Module arguments
    input wire  [16:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 17'b10000000000000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // vector$scls$1$dy_neg


module vector$scls$1$ex(x,y);
    
    // Module arguments
    input wire  [16:0] x;
    output reg  [34:0] y;
    
    // Constant declarations
    localparam  msb = 8'h10;
    localparam  ext = 35'h7fffe0000;
    
    // Update code
    always @(*) begin
        y = ((x) & 35'h7ffffffff);
        if (x[msb]) begin
            y = ((x) & 35'h7ffffffff) | ext;
        end
    end
    
endmodule // vector$scls$1$ex


module vector$scls$1$ey(x,y);
    
    // Module arguments
    input wire  [16:0] x;
    output reg  [34:0] y;
    
    // Constant declarations
    localparam  msb = 8'h10;
    localparam  ext = 35'h7fffe0000;
    
    // Update code
    always @(*) begin
        y = ((x) & 35'h7ffffffff);
        if (x[msb]) begin
            y = ((x) & 35'h7ffffffff) | ext;
        end
    end
    
endmodule // vector$scls$1$ey


module vector$scls$2(dx,dy,left,right,flat,owns,g,h);
    
    // Module arguments
    input wire  [16:0] dx;
    input wire  [16:0] dy;
    output reg  left;
    output reg  right;
    output reg  flat;
    output reg  owns;
    output reg  [34:0] g;
    output reg  [34:0] h;
    
    // Constant declarations
    localparam  frac = 8'h4;
    
    // Stub signals
    reg  [16:0] dx_neg$x;
    wire  dx_neg$neg;
    reg  [16:0] dy_neg$x;
    wire  dy_neg$neg;
    reg  [16:0] ex$x;
    wire  [34:0] ex$y;
    reg  [16:0] ey$x;
    wire  [34:0] ey$y;
    
    // Sub module instances
    vector$scls$2$dx_neg dx_neg(
        .x(dx_neg$x),
        .neg(dx_neg$neg)
    );
    vector$scls$2$dy_neg dy_neg(
        .x(dy_neg$x),
        .neg(dy_neg$neg)
    );
    vector$scls$2$ex ex(
        .x(ex$x),
        .y(ex$y)
    );
    vector$scls$2$ey ey(
        .x(ey$x),
        .y(ey$y)
    );
    
    // Update code
    always @(*) begin
        dx_neg$x = dx;
        dy_neg$x = dy;
        left = dy_neg$neg;
        flat = dy == 32'h0;
        right = ~dy_neg$neg & (dy != 32'h0);
        owns = dy_neg$neg | ((dy == 32'h0) & ~dx_neg$neg & (dx != 32'h0));
        ex$x = dx;
        ey$x = dy;
        g = ey$y << frac;
        h = ex$y << frac;
    end
    
endmodule // vector$scls$2


module vector$scls$2$dx_neg(x,neg);
    
    // Module arguments
    input wire  [16:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 17'b10000000000000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // vector$scls$2$dx_neg


module vector$scls$2$dy_neg(x,neg);
    
    // Module arguments
    input wire  [16:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 17'b10000000000000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // vector$scls$2$dy_neg


module vector$scls$2$ex(x,y);
    
    // Module arguments
    input wire  [16:0] x;
    output reg  [34:0] y;
    
    // Constant declarations
    localparam  msb = 8'h10;
    localparam  ext = 35'h7fffe0000;
    
    // Update code
    always @(*) begin
        y = ((x) & 35'h7ffffffff);
        if (x[msb]) begin
            y = ((x) & 35'h7ffffffff) | ext;
        end
    end
    
endmodule // vector$scls$2$ex


module vector$scls$2$ey(x,y);
    
    // Module arguments
    input wire  [16:0] x;
    output reg  [34:0] y;
    
    // Constant declarations
    localparam  msb = 8'h10;
    localparam  ext = 35'h7fffe0000;
    
    // Update code
    always @(*) begin
        y = ((x) & 35'h7ffffffff);
        if (x[msb]) begin
            y = ((x) & 35'h7ffffffff) | ext;
        end
    end
    
endmodule // vector$scls$2$ey


module vector$sdx$0(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$sdx$0


module vector$sdx$1(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$sdx$1


module vector$sdx$2(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$sdx$2


module vector$sdy$0(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$sdy$0


module vector$sdy$1(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$sdy$1


module vector$sdy$2(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$sdy$2


module vector$sl(d,q,clock);
    
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
          
endmodule // vector$sl


module vector$sp(d,q,clock);
    
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
          
endmodule // vector$sp


module vector$sr(d,q,clock);
    
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
          
endmodule // vector$sr


module vector$sv(d,q,clock);
    
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
          
endmodule // vector$sv


module vector$sx0(d,q,clock);
    
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
          
endmodule // vector$sx0


module vector$sx1(d,q,clock);
    
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
          
endmodule // vector$sx1


module vector$sy(d,q,clock);
    
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
          
endmodule // vector$sy


module vector$sy1(d,q,clock);
    
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
          
endmodule // vector$sy1


module vector$tag_dl(clock,en,d,q);
    
    // Module arguments
    input wire  clock;
    input wire  en;
    input wire  [19:0] d;
    output reg  [19:0] q;
    
    // Stub signals
    reg  [19:0] stages$0$d;
    wire  [19:0] stages$0$q;
    reg  stages$0$clock;
    reg  [19:0] stages$1$d;
    wire  [19:0] stages$1$q;
    reg  stages$1$clock;
    reg  [19:0] stages$2$d;
    wire  [19:0] stages$2$q;
    reg  stages$2$clock;
    reg  [19:0] stages$3$d;
    wire  [19:0] stages$3$q;
    reg  stages$3$clock;
    reg  [19:0] stages$4$d;
    wire  [19:0] stages$4$q;
    reg  stages$4$clock;
    reg  [19:0] stages$5$d;
    wire  [19:0] stages$5$q;
    reg  stages$5$clock;
    reg  [19:0] stages$6$d;
    wire  [19:0] stages$6$q;
    reg  stages$6$clock;
    reg  [19:0] stages$7$d;
    wire  [19:0] stages$7$q;
    reg  stages$7$clock;
    reg  [19:0] stages$8$d;
    wire  [19:0] stages$8$q;
    reg  stages$8$clock;
    reg  [19:0] stages$9$d;
    wire  [19:0] stages$9$q;
    reg  stages$9$clock;
    reg  [19:0] stages$10$d;
    wire  [19:0] stages$10$q;
    reg  stages$10$clock;
    reg  [19:0] stages$11$d;
    wire  [19:0] stages$11$q;
    reg  stages$11$clock;
    reg  [19:0] stages$12$d;
    wire  [19:0] stages$12$q;
    reg  stages$12$clock;
    reg  [19:0] stages$13$d;
    wire  [19:0] stages$13$q;
    reg  stages$13$clock;
    reg  [19:0] stages$14$d;
    wire  [19:0] stages$14$q;
    reg  stages$14$clock;
    reg  [19:0] stages$15$d;
    wire  [19:0] stages$15$q;
    reg  stages$15$clock;
    reg  [19:0] stages$16$d;
    wire  [19:0] stages$16$q;
    reg  stages$16$clock;
    reg  [19:0] stages$17$d;
    wire  [19:0] stages$17$q;
    reg  stages$17$clock;
    reg  [19:0] stages$18$d;
    wire  [19:0] stages$18$q;
    reg  stages$18$clock;
    reg  [19:0] stages$19$d;
    wire  [19:0] stages$19$q;
    reg  stages$19$clock;
    reg  [19:0] stages$20$d;
    wire  [19:0] stages$20$q;
    reg  stages$20$clock;
    reg  [19:0] stages$21$d;
    wire  [19:0] stages$21$q;
    reg  stages$21$clock;
    reg  [19:0] stages$22$d;
    wire  [19:0] stages$22$q;
    reg  stages$22$clock;
    reg  [19:0] stages$23$d;
    wire  [19:0] stages$23$q;
    reg  stages$23$clock;
    reg  [19:0] stages$24$d;
    wire  [19:0] stages$24$q;
    reg  stages$24$clock;
    reg  [19:0] stages$25$d;
    wire  [19:0] stages$25$q;
    reg  stages$25$clock;
    reg  [19:0] stages$26$d;
    wire  [19:0] stages$26$q;
    reg  stages$26$clock;
    reg  [19:0] stages$27$d;
    wire  [19:0] stages$27$q;
    reg  stages$27$clock;
    reg  [19:0] stages$28$d;
    wire  [19:0] stages$28$q;
    reg  stages$28$clock;
    reg  [19:0] stages$29$d;
    wire  [19:0] stages$29$q;
    reg  stages$29$clock;
    reg  [19:0] stages$30$d;
    wire  [19:0] stages$30$q;
    reg  stages$30$clock;
    reg  [19:0] stages$31$d;
    wire  [19:0] stages$31$q;
    reg  stages$31$clock;
    reg  [19:0] stages$32$d;
    wire  [19:0] stages$32$q;
    reg  stages$32$clock;
    reg  [19:0] stages$33$d;
    wire  [19:0] stages$33$q;
    reg  stages$33$clock;
    reg  [19:0] stages$34$d;
    wire  [19:0] stages$34$q;
    reg  stages$34$clock;
    reg  [19:0] stages$35$d;
    wire  [19:0] stages$35$q;
    reg  stages$35$clock;
    reg  [19:0] stages$36$d;
    wire  [19:0] stages$36$q;
    reg  stages$36$clock;
    reg  [19:0] stages$37$d;
    wire  [19:0] stages$37$q;
    reg  stages$37$clock;
    reg  [19:0] stages$38$d;
    wire  [19:0] stages$38$q;
    reg  stages$38$clock;
    reg  [19:0] stages$39$d;
    wire  [19:0] stages$39$q;
    reg  stages$39$clock;
    
    // Sub module instances
    vector$tag_dl$stages$0 stages$0(
        .d(stages$0$d),
        .q(stages$0$q),
        .clock(stages$0$clock)
    );
    vector$tag_dl$stages$1 stages$1(
        .d(stages$1$d),
        .q(stages$1$q),
        .clock(stages$1$clock)
    );
    vector$tag_dl$stages$2 stages$2(
        .d(stages$2$d),
        .q(stages$2$q),
        .clock(stages$2$clock)
    );
    vector$tag_dl$stages$3 stages$3(
        .d(stages$3$d),
        .q(stages$3$q),
        .clock(stages$3$clock)
    );
    vector$tag_dl$stages$4 stages$4(
        .d(stages$4$d),
        .q(stages$4$q),
        .clock(stages$4$clock)
    );
    vector$tag_dl$stages$5 stages$5(
        .d(stages$5$d),
        .q(stages$5$q),
        .clock(stages$5$clock)
    );
    vector$tag_dl$stages$6 stages$6(
        .d(stages$6$d),
        .q(stages$6$q),
        .clock(stages$6$clock)
    );
    vector$tag_dl$stages$7 stages$7(
        .d(stages$7$d),
        .q(stages$7$q),
        .clock(stages$7$clock)
    );
    vector$tag_dl$stages$8 stages$8(
        .d(stages$8$d),
        .q(stages$8$q),
        .clock(stages$8$clock)
    );
    vector$tag_dl$stages$9 stages$9(
        .d(stages$9$d),
        .q(stages$9$q),
        .clock(stages$9$clock)
    );
    vector$tag_dl$stages$10 stages$10(
        .d(stages$10$d),
        .q(stages$10$q),
        .clock(stages$10$clock)
    );
    vector$tag_dl$stages$11 stages$11(
        .d(stages$11$d),
        .q(stages$11$q),
        .clock(stages$11$clock)
    );
    vector$tag_dl$stages$12 stages$12(
        .d(stages$12$d),
        .q(stages$12$q),
        .clock(stages$12$clock)
    );
    vector$tag_dl$stages$13 stages$13(
        .d(stages$13$d),
        .q(stages$13$q),
        .clock(stages$13$clock)
    );
    vector$tag_dl$stages$14 stages$14(
        .d(stages$14$d),
        .q(stages$14$q),
        .clock(stages$14$clock)
    );
    vector$tag_dl$stages$15 stages$15(
        .d(stages$15$d),
        .q(stages$15$q),
        .clock(stages$15$clock)
    );
    vector$tag_dl$stages$16 stages$16(
        .d(stages$16$d),
        .q(stages$16$q),
        .clock(stages$16$clock)
    );
    vector$tag_dl$stages$17 stages$17(
        .d(stages$17$d),
        .q(stages$17$q),
        .clock(stages$17$clock)
    );
    vector$tag_dl$stages$18 stages$18(
        .d(stages$18$d),
        .q(stages$18$q),
        .clock(stages$18$clock)
    );
    vector$tag_dl$stages$19 stages$19(
        .d(stages$19$d),
        .q(stages$19$q),
        .clock(stages$19$clock)
    );
    vector$tag_dl$stages$20 stages$20(
        .d(stages$20$d),
        .q(stages$20$q),
        .clock(stages$20$clock)
    );
    vector$tag_dl$stages$21 stages$21(
        .d(stages$21$d),
        .q(stages$21$q),
        .clock(stages$21$clock)
    );
    vector$tag_dl$stages$22 stages$22(
        .d(stages$22$d),
        .q(stages$22$q),
        .clock(stages$22$clock)
    );
    vector$tag_dl$stages$23 stages$23(
        .d(stages$23$d),
        .q(stages$23$q),
        .clock(stages$23$clock)
    );
    vector$tag_dl$stages$24 stages$24(
        .d(stages$24$d),
        .q(stages$24$q),
        .clock(stages$24$clock)
    );
    vector$tag_dl$stages$25 stages$25(
        .d(stages$25$d),
        .q(stages$25$q),
        .clock(stages$25$clock)
    );
    vector$tag_dl$stages$26 stages$26(
        .d(stages$26$d),
        .q(stages$26$q),
        .clock(stages$26$clock)
    );
    vector$tag_dl$stages$27 stages$27(
        .d(stages$27$d),
        .q(stages$27$q),
        .clock(stages$27$clock)
    );
    vector$tag_dl$stages$28 stages$28(
        .d(stages$28$d),
        .q(stages$28$q),
        .clock(stages$28$clock)
    );
    vector$tag_dl$stages$29 stages$29(
        .d(stages$29$d),
        .q(stages$29$q),
        .clock(stages$29$clock)
    );
    vector$tag_dl$stages$30 stages$30(
        .d(stages$30$d),
        .q(stages$30$q),
        .clock(stages$30$clock)
    );
    vector$tag_dl$stages$31 stages$31(
        .d(stages$31$d),
        .q(stages$31$q),
        .clock(stages$31$clock)
    );
    vector$tag_dl$stages$32 stages$32(
        .d(stages$32$d),
        .q(stages$32$q),
        .clock(stages$32$clock)
    );
    vector$tag_dl$stages$33 stages$33(
        .d(stages$33$d),
        .q(stages$33$q),
        .clock(stages$33$clock)
    );
    vector$tag_dl$stages$34 stages$34(
        .d(stages$34$d),
        .q(stages$34$q),
        .clock(stages$34$clock)
    );
    vector$tag_dl$stages$35 stages$35(
        .d(stages$35$d),
        .q(stages$35$q),
        .clock(stages$35$clock)
    );
    vector$tag_dl$stages$36 stages$36(
        .d(stages$36$d),
        .q(stages$36$q),
        .clock(stages$36$clock)
    );
    vector$tag_dl$stages$37 stages$37(
        .d(stages$37$d),
        .q(stages$37$q),
        .clock(stages$37$clock)
    );
    vector$tag_dl$stages$38 stages$38(
        .d(stages$38$d),
        .q(stages$38$q),
        .clock(stages$38$clock)
    );
    vector$tag_dl$stages$39 stages$39(
        .d(stages$39$d),
        .q(stages$39$q),
        .clock(stages$39$clock)
    );
    
    // Update code
    always @(*) begin
        stages$0$clock = clock;
        stages$0$d = stages$0$q;
        stages$1$clock = clock;
        stages$1$d = stages$1$q;
        stages$2$clock = clock;
        stages$2$d = stages$2$q;
        stages$3$clock = clock;
        stages$3$d = stages$3$q;
        stages$4$clock = clock;
        stages$4$d = stages$4$q;
        stages$5$clock = clock;
        stages$5$d = stages$5$q;
        stages$6$clock = clock;
        stages$6$d = stages$6$q;
        stages$7$clock = clock;
        stages$7$d = stages$7$q;
        stages$8$clock = clock;
        stages$8$d = stages$8$q;
        stages$9$clock = clock;
        stages$9$d = stages$9$q;
        stages$10$clock = clock;
        stages$10$d = stages$10$q;
        stages$11$clock = clock;
        stages$11$d = stages$11$q;
        stages$12$clock = clock;
        stages$12$d = stages$12$q;
        stages$13$clock = clock;
        stages$13$d = stages$13$q;
        stages$14$clock = clock;
        stages$14$d = stages$14$q;
        stages$15$clock = clock;
        stages$15$d = stages$15$q;
        stages$16$clock = clock;
        stages$16$d = stages$16$q;
        stages$17$clock = clock;
        stages$17$d = stages$17$q;
        stages$18$clock = clock;
        stages$18$d = stages$18$q;
        stages$19$clock = clock;
        stages$19$d = stages$19$q;
        stages$20$clock = clock;
        stages$20$d = stages$20$q;
        stages$21$clock = clock;
        stages$21$d = stages$21$q;
        stages$22$clock = clock;
        stages$22$d = stages$22$q;
        stages$23$clock = clock;
        stages$23$d = stages$23$q;
        stages$24$clock = clock;
        stages$24$d = stages$24$q;
        stages$25$clock = clock;
        stages$25$d = stages$25$q;
        stages$26$clock = clock;
        stages$26$d = stages$26$q;
        stages$27$clock = clock;
        stages$27$d = stages$27$q;
        stages$28$clock = clock;
        stages$28$d = stages$28$q;
        stages$29$clock = clock;
        stages$29$d = stages$29$q;
        stages$30$clock = clock;
        stages$30$d = stages$30$q;
        stages$31$clock = clock;
        stages$31$d = stages$31$q;
        stages$32$clock = clock;
        stages$32$d = stages$32$q;
        stages$33$clock = clock;
        stages$33$d = stages$33$q;
        stages$34$clock = clock;
        stages$34$d = stages$34$q;
        stages$35$clock = clock;
        stages$35$d = stages$35$q;
        stages$36$clock = clock;
        stages$36$d = stages$36$q;
        stages$37$clock = clock;
        stages$37$d = stages$37$q;
        stages$38$clock = clock;
        stages$38$d = stages$38$q;
        stages$39$clock = clock;
        stages$39$d = stages$39$q;
        if (en) begin
            stages$0$d = d;
            stages$1$d = stages$0$q;
            stages$2$d = stages$1$q;
            stages$3$d = stages$2$q;
            stages$4$d = stages$3$q;
            stages$5$d = stages$4$q;
            stages$6$d = stages$5$q;
            stages$7$d = stages$6$q;
            stages$8$d = stages$7$q;
            stages$9$d = stages$8$q;
            stages$10$d = stages$9$q;
            stages$11$d = stages$10$q;
            stages$12$d = stages$11$q;
            stages$13$d = stages$12$q;
            stages$14$d = stages$13$q;
            stages$15$d = stages$14$q;
            stages$16$d = stages$15$q;
            stages$17$d = stages$16$q;
            stages$18$d = stages$17$q;
            stages$19$d = stages$18$q;
            stages$20$d = stages$19$q;
            stages$21$d = stages$20$q;
            stages$22$d = stages$21$q;
            stages$23$d = stages$22$q;
            stages$24$d = stages$23$q;
            stages$25$d = stages$24$q;
            stages$26$d = stages$25$q;
            stages$27$d = stages$26$q;
            stages$28$d = stages$27$q;
            stages$29$d = stages$28$q;
            stages$30$d = stages$29$q;
            stages$31$d = stages$30$q;
            stages$32$d = stages$31$q;
            stages$33$d = stages$32$q;
            stages$34$d = stages$33$q;
            stages$35$d = stages$34$q;
            stages$36$d = stages$35$q;
            stages$37$d = stages$36$q;
            stages$38$d = stages$37$q;
            stages$39$d = stages$38$q;
        end
        q = stages$39$q;
    end
    
endmodule // vector$tag_dl


module vector$tag_dl$stages$0(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$tag_dl$stages$0


module vector$tag_dl$stages$1(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$tag_dl$stages$1


module vector$tag_dl$stages$10(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$tag_dl$stages$10


module vector$tag_dl$stages$11(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$tag_dl$stages$11


module vector$tag_dl$stages$12(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$tag_dl$stages$12


module vector$tag_dl$stages$13(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$tag_dl$stages$13


module vector$tag_dl$stages$14(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$tag_dl$stages$14


module vector$tag_dl$stages$15(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$tag_dl$stages$15


module vector$tag_dl$stages$16(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$tag_dl$stages$16


module vector$tag_dl$stages$17(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$tag_dl$stages$17


module vector$tag_dl$stages$18(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$tag_dl$stages$18


module vector$tag_dl$stages$19(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$tag_dl$stages$19


module vector$tag_dl$stages$2(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$tag_dl$stages$2


module vector$tag_dl$stages$20(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$tag_dl$stages$20


module vector$tag_dl$stages$21(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$tag_dl$stages$21


module vector$tag_dl$stages$22(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$tag_dl$stages$22


module vector$tag_dl$stages$23(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$tag_dl$stages$23


module vector$tag_dl$stages$24(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$tag_dl$stages$24


module vector$tag_dl$stages$25(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$tag_dl$stages$25


module vector$tag_dl$stages$26(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$tag_dl$stages$26


module vector$tag_dl$stages$27(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$tag_dl$stages$27


module vector$tag_dl$stages$28(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$tag_dl$stages$28


module vector$tag_dl$stages$29(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$tag_dl$stages$29


module vector$tag_dl$stages$3(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$tag_dl$stages$3


module vector$tag_dl$stages$30(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$tag_dl$stages$30


module vector$tag_dl$stages$31(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$tag_dl$stages$31


module vector$tag_dl$stages$32(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$tag_dl$stages$32


module vector$tag_dl$stages$33(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$tag_dl$stages$33


module vector$tag_dl$stages$34(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$tag_dl$stages$34


module vector$tag_dl$stages$35(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$tag_dl$stages$35


module vector$tag_dl$stages$36(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$tag_dl$stages$36


module vector$tag_dl$stages$37(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$tag_dl$stages$37


module vector$tag_dl$stages$38(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$tag_dl$stages$38


module vector$tag_dl$stages$39(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$tag_dl$stages$39


module vector$tag_dl$stages$4(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$tag_dl$stages$4


module vector$tag_dl$stages$5(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$tag_dl$stages$5


module vector$tag_dl$stages$6(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$tag_dl$stages$6


module vector$tag_dl$stages$7(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$tag_dl$stages$7


module vector$tag_dl$stages$8(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$tag_dl$stages$8


module vector$tag_dl$stages$9(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // vector$tag_dl$stages$9


module vector$te(d,q,clock);
    
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
          
endmodule // vector$te


module vector$top_xr(d,q,clock);
    
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
          
endmodule // vector$top_xr


module vector$tv(d,q,clock);
    
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
          
endmodule // vector$tv


module vector$tx(d,q,clock);
    
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
          
endmodule // vector$tx


module vector$ty(d,q,clock);
    
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
          
endmodule // vector$ty


module vector$vc$0(d,q,clock);
    
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
          
endmodule // vector$vc$0


module vector$vc$1(d,q,clock);
    
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
          
endmodule // vector$vc$1


module vector$vc$2(d,q,clock);
    
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
          
endmodule // vector$vc$2


module vector$vc$3(d,q,clock);
    
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
          
endmodule // vector$vc$3


module vector$vc$4(d,q,clock);
    
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
          
endmodule // vector$vc$4


module vector$vc$5(d,q,clock);
    
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
          
endmodule // vector$vc$5


module vector$vc$6(d,q,clock);
    
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
          
endmodule // vector$vc$6


module vector$vc$7(d,q,clock);
    
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
          
endmodule // vector$vc$7


module vector$vc$8(d,q,clock);
    
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
          
endmodule // vector$vc$8


module vector$viw$0(d,q,clock);
    
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
          
endmodule // vector$viw$0


module vector$viw$1(d,q,clock);
    
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
          
endmodule // vector$viw$1


module vector$viw$2(d,q,clock);
    
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
          
endmodule // vector$viw$2


module vector$vx$0(d,q,clock);
    
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
          
endmodule // vector$vx$0


module vector$vx$1(d,q,clock);
    
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
          
endmodule // vector$vx$1


module vector$vx$2(d,q,clock);
    
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
          
endmodule // vector$vx$2


module vector$vy$0(d,q,clock);
    
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
          
endmodule // vector$vy$0


module vector$vy$1(d,q,clock);
    
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
          
endmodule // vector$vy$1


module vector$vy$2(d,q,clock);
    
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
          
endmodule // vector$vy$2


module vector$vz$0(d,q,clock);
    
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
          
endmodule // vector$vz$0


module vector$vz$1(d,q,clock);
    
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
          
endmodule // vector$vz$1


module vector$vz$2(d,q,clock);
    
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
          
endmodule // vector$vz$2


module vector$w$0(d,q,clock);
    
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
          
endmodule // vector$w$0


module vector$w$1(d,q,clock);
    
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
          
endmodule // vector$w$1


module vector$w$2(d,q,clock);
    
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
          
endmodule // vector$w$2


module vector$w0$0(d,q,clock);
    
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
          
endmodule // vector$w0$0


module vector$w0$1(d,q,clock);
    
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
          
endmodule // vector$w0$1


module vector$w0$2(d,q,clock);
    
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
          
endmodule // vector$w0$2


module vector$wown$0(d,q,clock);
    
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
          
endmodule // vector$wown$0


module vector$wown$1(d,q,clock);
    
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
          
endmodule // vector$wown$1


module vector$wown$2(d,q,clock);
    
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
          
endmodule // vector$wown$2


module vector$wp(d,q,clock);
    
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
          
endmodule // vector$wp


module vector$wstep$0(d,q,clock);
    
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
          
endmodule // vector$wstep$0


module vector$wstep$1(d,q,clock);
    
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
          
endmodule // vector$wstep$1


module vector$wstep$2(d,q,clock);
    
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
          
endmodule // vector$wstep$2


module vector$wx0(d,q,clock);
    
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
          
endmodule // vector$wx0


module vector$wx1(d,q,clock);
    
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
          
endmodule // vector$wx1
