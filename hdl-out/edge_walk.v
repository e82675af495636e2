

module edge_walk(clock,height,inp$valid,inp$ready,inp$walk,inp$maj_left,inp$maj_j,inp$maj_count,inp$maj_x,inp$maj_r,inp$maj_q,inp$maj_rho,inp$maj_d,inp$maj_at_z,inp$maj_at_c0,inp$maj_at_c1,inp$maj_at_c2,inp$maj_inc0_z,inp$maj_inc0_c0,inp$maj_inc0_c1,inp$maj_inc0_c2,inp$maj_inc1_z,inp$maj_inc1_c0,inp$maj_inc1_c1,inp$maj_inc1_c2,inp$short0_j,inp$short0_count,inp$short0_x,inp$short0_r,inp$short0_q,inp$short0_rho,inp$short0_d,inp$short0_at_z,inp$short0_at_c0,inp$short0_at_c1,inp$short0_at_c2,inp$short0_inc0_z,inp$short0_inc0_c0,inp$short0_inc0_c1,inp$short0_inc0_c2,inp$short0_inc1_z,inp$short0_inc1_c0,inp$short0_inc1_c1,inp$short0_inc1_c2,inp$short1_j,inp$short1_count,inp$short1_x,inp$short1_r,inp$short1_q,inp$short1_rho,inp$short1_d,inp$short1_at_z,inp$short1_at_c0,inp$short1_at_c1,inp$short1_at_c2,inp$short1_inc0_z,inp$short1_inc0_c0,inp$short1_inc0_c1,inp$short1_inc0_c2,inp$short1_inc1_z,inp$short1_inc1_c0,inp$short1_inc1_c1,inp$short1_inc1_c2,inp$ddx_z,inp$ddx_c0,inp$ddx_c1,inp$ddx_c2,out$valid,out$ready,out$y,out$xl,out$xr,out$left_z,out$left_c0,out$left_c1,out$left_c2,out$right_z,out$right_c0,out$right_c1,out$right_c2,out$ddx_z,out$ddx_c0,out$ddx_c1,out$ddx_c2,hold,idle,free_next);
    
    // Module arguments
    input wire  clock;
    input wire  [10:0] height;
    input wire  inp$valid;
    output reg  inp$ready;
    input wire  inp$walk;
    input wire  inp$maj_left;
    input wire  [12:0] inp$maj_j;
    input wire  [12:0] inp$maj_count;
    input wire  [12:0] inp$maj_x;
    input wire  [20:0] inp$maj_r;
    input wire  [16:0] inp$maj_q;
    input wire  [20:0] inp$maj_rho;
    input wire  [20:0] inp$maj_d;
    input wire  [35:0] inp$maj_at_z;
    input wire  [31:0] inp$maj_at_c0;
    input wire  [31:0] inp$maj_at_c1;
    input wire  [31:0] inp$maj_at_c2;
    input wire  [39:0] inp$maj_inc0_z;
    input wire  [35:0] inp$maj_inc0_c0;
    input wire  [35:0] inp$maj_inc0_c1;
    input wire  [35:0] inp$maj_inc0_c2;
    input wire  [39:0] inp$maj_inc1_z;
    input wire  [35:0] inp$maj_inc1_c0;
    input wire  [35:0] inp$maj_inc1_c1;
    input wire  [35:0] inp$maj_inc1_c2;
    input wire  [12:0] inp$short0_j;
    input wire  [12:0] inp$short0_count;
    input wire  [12:0] inp$short0_x;
    input wire  [20:0] inp$short0_r;
    input wire  [16:0] inp$short0_q;
    input wire  [20:0] inp$short0_rho;
    input wire  [20:0] inp$short0_d;
    input wire  [35:0] inp$short0_at_z;
    input wire  [31:0] inp$short0_at_c0;
    input wire  [31:0] inp$short0_at_c1;
    input wire  [31:0] inp$short0_at_c2;
    input wire  [39:0] inp$short0_inc0_z;
    input wire  [35:0] inp$short0_inc0_c0;
    input wire  [35:0] inp$short0_inc0_c1;
    input wire  [35:0] inp$short0_inc0_c2;
    input wire  [39:0] inp$short0_inc1_z;
    input wire  [35:0] inp$short0_inc1_c0;
    input wire  [35:0] inp$short0_inc1_c1;
    input wire  [35:0] inp$short0_inc1_c2;
    input wire  [12:0] inp$short1_j;
    input wire  [12:0] inp$short1_count;
    input wire  [12:0] inp$short1_x;
    input wire  [20:0] inp$short1_r;
    input wire  [16:0] inp$short1_q;
    input wire  [20:0] inp$short1_rho;
    input wire  [20:0] inp$short1_d;
    input wire  [35:0] inp$short1_at_z;
    input wire  [31:0] inp$short1_at_c0;
    input wire  [31:0] inp$short1_at_c1;
    input wire  [31:0] inp$short1_at_c2;
    input wire  [39:0] inp$short1_inc0_z;
    input wire  [35:0] inp$short1_inc0_c0;
    input wire  [35:0] inp$short1_inc0_c1;
    input wire  [35:0] inp$short1_inc0_c2;
    input wire  [39:0] inp$short1_inc1_z;
    input wire  [35:0] inp$short1_inc1_c0;
    input wire  [35:0] inp$short1_inc1_c1;
    input wire  [35:0] inp$short1_inc1_c2;
    input wire  [39:0] inp$ddx_z;
    input wire  [35:0] inp$ddx_c0;
    input wire  [35:0] inp$ddx_c1;
    input wire  [35:0] inp$ddx_c2;
    output reg  out$valid;
    input wire  out$ready;
    output reg  [9:0] out$y;
    output reg  [12:0] out$xl;
    output reg  [12:0] out$xr;
    output reg  [35:0] out$left_z;
    output reg  [31:0] out$left_c0;
    output reg  [31:0] out$left_c1;
    output reg  [31:0] out$left_c2;
    output reg  [35:0] out$right_z;
    output reg  [31:0] out$right_c0;
    output reg  [31:0] out$right_c1;
    output reg  [31:0] out$right_c2;
    output reg  [39:0] out$ddx_z;
    output reg  [35:0] out$ddx_c0;
    output reg  [35:0] out$ddx_c1;
    output reg  [35:0] out$ddx_c2;
    input wire  hold;
    output reg  idle;
    output reg  free_next;
    
    // Stub signals
    wire  clip_y$on;
    reg  maj$clock;
    reg  maj$load;
    reg  maj$step;
    reg  maj$up;
    reg  [12:0] maj$ld_x;
    reg  [12:0] maj$ld_q;
    reg  [21:0] maj$ld_t;
    reg  [21:0] maj$ld_a;
    reg  [21:0] maj$ld_b;
    reg  [35:0] maj$ld_at_z;
    reg  [31:0] maj$ld_at_c0;
    reg  [31:0] maj$ld_at_c1;
    reg  [31:0] maj$ld_at_c2;
    reg  [35:0] maj$ld_inc0_z;
    reg  [31:0] maj$ld_inc0_c0;
    reg  [31:0] maj$ld_inc0_c1;
    reg  [31:0] maj$ld_inc0_c2;
    reg  [35:0] maj$ld_inc1_z;
    reg  [31:0] maj$ld_inc1_c0;
    reg  [31:0] maj$ld_inc1_c1;
    reg  [31:0] maj$ld_inc1_c2;
    wire  [12:0] maj$x;
    wire  [35:0] maj$at_z;
    wire  [31:0] maj$at_c0;
    wire  [31:0] maj$at_c1;
    wire  [31:0] maj$at_c2;
    reg  cur$clock;
    reg  cur$load;
    reg  cur$step;
    reg  cur$up;
    reg  [12:0] cur$ld_x;
    reg  [12:0] cur$ld_q;
    reg  [21:0] cur$ld_t;
    reg  [21:0] cur$ld_a;
    reg  [21:0] cur$ld_b;
    reg  [35:0] cur$ld_at_z;
    reg  [31:0] cur$ld_at_c0;
    reg  [31:0] cur$ld_at_c1;
    reg  [31:0] cur$ld_at_c2;
    reg  [35:0] cur$ld_inc0_z;
    reg  [31:0] cur$ld_inc0_c0;
    reg  [31:0] cur$ld_inc0_c1;
    reg  [31:0] cur$ld_inc0_c2;
    reg  [35:0] cur$ld_inc1_z;
    reg  [31:0] cur$ld_inc1_c0;
    reg  [31:0] cur$ld_inc1_c1;
    reg  [31:0] cur$ld_inc1_c2;
    wire  [12:0] cur$x;
    wire  [35:0] cur$at_z;
    wire  [31:0] cur$at_c0;
    wire  [31:0] cur$at_c1;
    wire  [31:0] cur$at_c2;
    reg  start_maj$up;
    reg  [20:0] start_maj$r;
    reg  [20:0] start_maj$rho;
    reg  [20:0] start_maj$d;
    wire  [21:0] start_maj$t;
    wire  [21:0] start_maj$a;
    wire  [21:0] start_maj$b;
    reg  start_s0$up;
    reg  [20:0] start_s0$r;
    reg  [20:0] start_s0$rho;
    reg  [20:0] start_s0$d;
    wire  [21:0] start_s0$t;
    wire  [21:0] start_s0$a;
    wire  [21:0] start_s0$b;
    reg  start_s1$up;
    reg  [20:0] start_s1$r;
    reg  [20:0] start_s1$rho;
    reg  [20:0] start_s1$d;
    wire  [21:0] start_s1$t;
    wire  [21:0] start_s1$a;
    wire  [21:0] start_s1$b;
    reg  busy$d;
    wire  busy$q;
    reg  busy$clock;
    reg  walking$d;
    wire  walking$q;
    reg  walking$clock;
    reg  up$d;
    wire  up$q;
    reg  up$clock;
    reg  maj_left$d;
    wire  maj_left$q;
    reg  maj_left$clock;
    reg  [12:0] j$d;
    wire  [12:0] j$q;
    reg  j$clock;
    reg  [12:0] rem$d;
    wire  [12:0] rem$q;
    reg  rem$clock;
    reg  [12:0] crow$d;
    wire  [12:0] crow$q;
    reg  crow$clock;
    reg  [12:0] crem$d;
    wire  [12:0] crem$q;
    reg  crem$clock;
    reg  last_r$d;
    wire  last_r$q;
    reg  last_r$clock;
    reg  sw_r$d;
    wire  sw_r$q;
    reg  sw_r$clock;
    reg  [39:0] ddx_z$d;
    wire  [39:0] ddx_z$q;
    reg  ddx_z$clock;
    reg  [35:0] ddx_c0$d;
    wire  [35:0] ddx_c0$q;
    reg  ddx_c0$clock;
    reg  [35:0] ddx_c1$d;
    wire  [35:0] ddx_c1$q;
    reg  ddx_c1$clock;
    reg  [35:0] ddx_c2$d;
    wire  [35:0] ddx_c2$q;
    reg  ddx_c2$clock;
    reg  [12:0] pend_x$d;
    wire  [12:0] pend_x$q;
    reg  pend_x$clock;
    reg  [12:0] pend_q$d;
    wire  [12:0] pend_q$q;
    reg  pend_q$clock;
    reg  [21:0] pend_t$d;
    wire  [21:0] pend_t$q;
    reg  pend_t$clock;
    reg  [21:0] pend_a$d;
    wire  [21:0] pend_a$q;
    reg  pend_a$clock;
    reg  [21:0] pend_b$d;
    wire  [21:0] pend_b$q;
    reg  pend_b$clock;
    reg  [35:0] pend_at_z$d;
    wire  [35:0] pend_at_z$q;
    reg  pend_at_z$clock;
    reg  [31:0] pend_at_c0$d;
    wire  [31:0] pend_at_c0$q;
    reg  pend_at_c0$clock;
    reg  [31:0] pend_at_c1$d;
    wire  [31:0] pend_at_c1$q;
    reg  pend_at_c1$clock;
    reg  [31:0] pend_at_c2$d;
    wire  [31:0] pend_at_c2$q;
    reg  pend_at_c2$clock;
    reg  [35:0] pend_inc0_z$d;
    wire  [35:0] pend_inc0_z$q;
    reg  pend_inc0_z$clock;
    reg  [31:0] pend_inc0_c0$d;
    wire  [31:0] pend_inc0_c0$q;
    reg  pend_inc0_c0$clock;
    reg  [31:0] pend_inc0_c1$d;
    wire  [31:0] pend_inc0_c1$q;
    reg  pend_inc0_c1$clock;
    reg  [31:0] pend_inc0_c2$d;
    wire  [31:0] pend_inc0_c2$q;
    reg  pend_inc0_c2$clock;
    reg  [35:0] pend_inc1_z$d;
    wire  [35:0] pend_inc1_z$q;
    reg  pend_inc1_z$clock;
    reg  [31:0] pend_inc1_c0$d;
    wire  [31:0] pend_inc1_c0$q;
    reg  pend_inc1_c0$clock;
    reg  [31:0] pend_inc1_c1$d;
    wire  [31:0] pend_inc1_c1$q;
    reg  pend_inc1_c1$clock;
    reg  [31:0] pend_inc1_c2$d;
    wire  [31:0] pend_inc1_c2$q;
    reg  pend_inc1_c2$clock;
    reg  o_valid$d;
    wire  o_valid$q;
    reg  o_valid$clock;
    reg  [9:0] o_y$d;
    wire  [9:0] o_y$q;
    reg  o_y$clock;
    reg  [12:0] o_xl$d;
    wire  [12:0] o_xl$q;
    reg  o_xl$clock;
    reg  [12:0] o_xr$d;
    wire  [12:0] o_xr$q;
    reg  o_xr$clock;
    reg  [35:0] o_left_z$d;
    wire  [35:0] o_left_z$q;
    reg  o_left_z$clock;
    reg  [31:0] o_left_c0$d;
    wire  [31:0] o_left_c0$q;
    reg  o_left_c0$clock;
    reg  [31:0] o_left_c1$d;
    wire  [31:0] o_left_c1$q;
    reg  o_left_c1$clock;
    reg  [31:0] o_left_c2$d;
    wire  [31:0] o_left_c2$q;
    reg  o_left_c2$clock;
    reg  [35:0] o_right_z$d;
    wire  [35:0] o_right_z$q;
    reg  o_right_z$clock;
    reg  [31:0] o_right_c0$d;
    wire  [31:0] o_right_c0$q;
    reg  o_right_c0$clock;
    reg  [31:0] o_right_c1$d;
    wire  [31:0] o_right_c1$q;
    reg  o_right_c1$clock;
    reg  [31:0] o_right_c2$d;
    wire  [31:0] o_right_c2$q;
    reg  o_right_c2$clock;
    reg  [12:0] j_sign$x;
    wire  j_sign$neg;
    reg  [12:0] sides$a;
    reg  [12:0] sides$b;
    wire  sides$lt;
    reg  [12:0] in_j_sign$x;
    wire  in_j_sign$neg;
    
    // Local signals
    reg  accept;
    reg  in_up;
    reg  in_no_rows;
    reg  [12:0] in_crow;
    reg  in_last;
    reg  in_short0_none;
    reg  [12:0] height_j;
    reg  free;
    reg  emit;
    reg  step;
    reg  valid;
    reg  [12:0] j_next;
    
    // Sub module instances
    edge_walk$clip_y clip_y(
        .on(clip_y$on)
    );
    edge_walk$maj maj(
        .clock(maj$clock),
        .load(maj$load),
        .step(maj$step),
        .up(maj$up),
        .ld_x(maj$ld_x),
        .ld_q(maj$ld_q),
        .ld_t(maj$ld_t),
        .ld_a(maj$ld_a),
        .ld_b(maj$ld_b),
        .ld_at_z(maj$ld_at_z),
        .ld_at_c0(maj$ld_at_c0),
        .ld_at_c1(maj$ld_at_c1),
        .ld_at_c2(maj$ld_at_c2),
        .ld_inc0_z(maj$ld_inc0_z),
        .ld_inc0_c0(maj$ld_inc0_c0),
        .ld_inc0_c1(maj$ld_inc0_c1),
        .ld_inc0_c2(maj$ld_inc0_c2),
        .ld_inc1_z(maj$ld_inc1_z),
        .ld_inc1_c0(maj$ld_inc1_c0),
        .ld_inc1_c1(maj$ld_inc1_c1),
        .ld_inc1_c2(maj$ld_inc1_c2),
        .x(maj$x),
        .at_z(maj$at_z),
        .at_c0(maj$at_c0),
        .at_c1(maj$at_c1),
        .at_c2(maj$at_c2)
    );
    edge_walk$cur cur(
        .clock(cur$clock),
        .load(cur$load),
        .step(cur$step),
        .up(cur$up),
        .ld_x(cur$ld_x),
        .ld_q(cur$ld_q),
        .ld_t(cur$ld_t),
        .ld_a(cur$ld_a),
        .ld_b(cur$ld_b),
        .ld_at_z(cur$ld_at_z),
        .ld_at_c0(cur$ld_at_c0),
        .ld_at_c1(cur$ld_at_c1),
        .ld_at_c2(cur$ld_at_c2),
        .ld_inc0_z(cur$ld_inc0_z),
        .ld_inc0_c0(cur$ld_inc0_c0),
        .ld_inc0_c1(cur$ld_inc0_c1),
        .ld_inc0_c2(cur$ld_inc0_c2),
        .ld_inc1_z(cur$ld_inc1_z),
        .ld_inc1_c0(cur$ld_inc1_c0),
        .ld_inc1_c1(cur$ld_inc1_c1),
        .ld_inc1_c2(cur$ld_inc1_c2),
        .x(cur$x),
        .at_z(cur$at_z),
        .at_c0(cur$at_c0),
        .at_c1(cur$at_c1),
        .at_c2(cur$at_c2)
    );
    edge_walk$start_maj start_maj(
        .up(start_maj$up),
        .r(start_maj$r),
        .rho(start_maj$rho),
        .d(start_maj$d),
        .t(start_maj$t),
        .a(start_maj$a),
        .b(start_maj$b)
    );
    edge_walk$start_s0 start_s0(
        .up(start_s0$up),
        .r(start_s0$r),
        .rho(start_s0$rho),
        .d(start_s0$d),
        .t(start_s0$t),
        .a(start_s0$a),
        .b(start_s0$b)
    );
    edge_walk$start_s1 start_s1(
        .up(start_s1$up),
        .r(start_s1$r),
        .rho(start_s1$rho),
        .d(start_s1$d),
        .t(start_s1$t),
        .a(start_s1$a),
        .b(start_s1$b)
    );
    edge_walk$busy busy(
        .d(busy$d),
        .q(busy$q),
        .clock(busy$clock)
    );
    edge_walk$walking walking(
        .d(walking$d),
        .q(walking$q),
        .clock(walking$clock)
    );
    edge_walk$up up(
        .d(up$d),
        .q(up$q),
        .clock(up$clock)
    );
    edge_walk$maj_left maj_left(
        .d(maj_left$d),
        .q(maj_left$q),
        .clock(maj_left$clock)
    );
    edge_walk$j j(
        .d(j$d),
        .q(j$q),
        .clock(j$clock)
    );
    edge_walk$rem rem(
        .d(rem$d),
        .q(rem$q),
        .clock(rem$clock)
    );
    edge_walk$crow crow(
        .d(crow$d),
        .q(crow$q),
        .clock(crow$clock)
    );
    edge_walk$crem crem(
        .d(crem$d),
        .q(crem$q),
        .clock(crem$clock)
    );
    edge_walk$last_r last_r(
        .d(last_r$d),
        .q(last_r$q),
        .clock(last_r$clock)
    );
    edge_walk$sw_r sw_r(
        .d(sw_r$d),
        .q(sw_r$q),
        .clock(sw_r$clock)
    );
    edge_walk$ddx_z ddx_z(
        .d(ddx_z$d),
        .q(ddx_z$q),
        .clock(ddx_z$clock)
    );
    edge_walk$ddx_c0 ddx_c0(
        .d(ddx_c0$d),
        .q(ddx_c0$q),
        .clock(ddx_c0$clock)
    );
    edge_walk$ddx_c1 ddx_c1(
        .d(ddx_c1$d),
        .q(ddx_c1$q),
        .clock(ddx_c1$clock)
    );
    edge_walk$ddx_c2 ddx_c2(
        .d(ddx_c2$d),
        .q(ddx_c2$q),
        .clock(ddx_c2$clock)
    );
    edge_walk$pend_x pend_x(
        .d(pend_x$d),
        .q(pend_x$q),
        .clock(pend_x$clock)
    );
    edge_walk$pend_q pend_q(
        .d(pend_q$d),
        .q(pend_q$q),
        .clock(pend_q$clock)
    );
    edge_walk$pend_t pend_t(
        .d(pend_t$d),
        .q(pend_t$q),
        .clock(pend_t$clock)
    );
    edge_walk$pend_a pend_a(
        .d(pend_a$d),
        .q(pend_a$q),
        .clock(pend_a$clock)
    );
    edge_walk$pend_b pend_b(
        .d(pend_b$d),
        .q(pend_b$q),
        .clock(pend_b$clock)
    );
    edge_walk$pend_at_z pend_at_z(
        .d(pend_at_z$d),
        .q(pend_at_z$q),
        .clock(pend_at_z$clock)
    );
    edge_walk$pend_at_c0 pend_at_c0(
        .d(pend_at_c0$d),
        .q(pend_at_c0$q),
        .clock(pend_at_c0$clock)
    );
    edge_walk$pend_at_c1 pend_at_c1(
        .d(pend_at_c1$d),
        .q(pend_at_c1$q),
        .clock(pend_at_c1$clock)
    );
    edge_walk$pend_at_c2 pend_at_c2(
        .d(pend_at_c2$d),
        .q(pend_at_c2$q),
        .clock(pend_at_c2$clock)
    );
    edge_walk$pend_inc0_z pend_inc0_z(
        .d(pend_inc0_z$d),
        .q(pend_inc0_z$q),
        .clock(pend_inc0_z$clock)
    );
    edge_walk$pend_inc0_c0 pend_inc0_c0(
        .d(pend_inc0_c0$d),
        .q(pend_inc0_c0$q),
        .clock(pend_inc0_c0$clock)
    );
    edge_walk$pend_inc0_c1 pend_inc0_c1(
        .d(pend_inc0_c1$d),
        .q(pend_inc0_c1$q),
        .clock(pend_inc0_c1$clock)
    );
    edge_walk$pend_inc0_c2 pend_inc0_c2(
        .d(pend_inc0_c2$d),
        .q(pend_inc0_c2$q),
        .clock(pend_inc0_c2$clock)
    );
    edge_walk$pend_inc1_z pend_inc1_z(
        .d(pend_inc1_z$d),
        .q(pend_inc1_z$q),
        .clock(pend_inc1_z$clock)
    );
    edge_walk$pend_inc1_c0 pend_inc1_c0(
        .d(pend_inc1_c0$d),
        .q(pend_inc1_c0$q),
        .clock(pend_inc1_c0$clock)
    );
    edge_walk$pend_inc1_c1 pend_inc1_c1(
        .d(pend_inc1_c1$d),
        .q(pend_inc1_c1$q),
        .clock(pend_inc1_c1$clock)
    );
    edge_walk$pend_inc1_c2 pend_inc1_c2(
        .d(pend_inc1_c2$d),
        .q(pend_inc1_c2$q),
        .clock(pend_inc1_c2$clock)
    );
    edge_walk$o_valid o_valid(
        .d(o_valid$d),
        .q(o_valid$q),
        .clock(o_valid$clock)
    );
    edge_walk$o_y o_y(
        .d(o_y$d),
        .q(o_y$q),
        .clock(o_y$clock)
    );
    edge_walk$o_xl o_xl(
        .d(o_xl$d),
        .q(o_xl$q),
        .clock(o_xl$clock)
    );
    edge_walk$o_xr o_xr(
        .d(o_xr$d),
        .q(o_xr$q),
        .clock(o_xr$clock)
    );
    edge_walk$o_left_z o_left_z(
        .d(o_left_z$d),
        .q(o_left_z$q),
        .clock(o_left_z$clock)
    );
    edge_walk$o_left_c0 o_left_c0(
        .d(o_left_c0$d),
        .q(o_left_c0$q),
        .clock(o_left_c0$clock)
    );
    edge_walk$o_left_c1 o_left_c1(
        .d(o_left_c1$d),
        .q(o_left_c1$q),
        .clock(o_left_c1$clock)
    );
    edge_walk$o_left_c2 o_left_c2(
        .d(o_left_c2$d),
        .q(o_left_c2$q),
        .clock(o_left_c2$clock)
    );
    edge_walk$o_right_z o_right_z(
        .d(o_right_z$d),
        .q(o_right_z$q),
        .clock(o_right_z$clock)
    );
    edge_walk$o_right_c0 o_right_c0(
        .d(o_right_c0$d),
        .q(o_right_c0$q),
        .clock(o_right_c0$clock)
    );
    edge_walk$o_right_c1 o_right_c1(
        .d(o_right_c1$d),
        .q(o_right_c1$q),
        .clock(o_right_c1$clock)
    );
    edge_walk$o_right_c2 o_right_c2(
        .d(o_right_c2$d),
        .q(o_right_c2$q),
        .clock(o_right_c2$clock)
    );
    edge_walk$j_sign j_sign(
        .x(j_sign$x),
        .neg(j_sign$neg)
    );
    edge_walk$sides sides(
        .a(sides$a),
        .b(sides$b),
        .lt(sides$lt)
    );
    edge_walk$in_j_sign in_j_sign(
        .x(in_j_sign$x),
        .neg(in_j_sign$neg)
    );
    
    // Update code
    always @(*) begin
        busy$clock = clock;
        walking$clock = clock;
        up$clock = clock;
        maj_left$clock = clock;
        j$clock = clock;
        rem$clock = clock;
        crow$clock = clock;
        crem$clock = clock;
        last_r$clock = clock;
        sw_r$clock = clock;
        ddx_z$clock = clock;
        ddx_c0$clock = clock;
        ddx_c1$clock = clock;
        ddx_c2$clock = clock;
        pend_x$clock = clock;
        pend_q$clock = clock;
        pend_t$clock = clock;
        pend_a$clock = clock;
        pend_b$clock = clock;
        pend_at_z$clock = clock;
        pend_at_c0$clock = clock;
        pend_at_c1$clock = clock;
        pend_at_c2$clock = clock;
        pend_inc0_z$clock = clock;
        pend_inc0_c0$clock = clock;
        pend_inc0_c1$clock = clock;
        pend_inc0_c2$clock = clock;
        pend_inc1_z$clock = clock;
        pend_inc1_c0$clock = clock;
        pend_inc1_c1$clock = clock;
        pend_inc1_c2$clock = clock;
        o_valid$clock = clock;
        o_y$clock = clock;
        o_xl$clock = clock;
        o_xr$clock = clock;
        o_left_z$clock = clock;
        o_left_c0$clock = clock;
        o_left_c1$clock = clock;
        o_left_c2$clock = clock;
        o_right_z$clock = clock;
        o_right_c0$clock = clock;
        o_right_c1$clock = clock;
        o_right_c2$clock = clock;
        busy$d = busy$q;
        walking$d = walking$q;
        up$d = up$q;
        maj_left$d = maj_left$q;
        j$d = j$q;
        rem$d = rem$q;
        crow$d = crow$q;
        crem$d = crem$q;
        last_r$d = last_r$q;
        sw_r$d = sw_r$q;
        ddx_z$d = ddx_z$q;
        ddx_c0$d = ddx_c0$q;
        ddx_c1$d = ddx_c1$q;
        ddx_c2$d = ddx_c2$q;
        pend_x$d = pend_x$q;
        pend_q$d = pend_q$q;
        pend_t$d = pend_t$q;
        pend_a$d = pend_a$q;
        pend_b$d = pend_b$q;
        pend_at_z$d = pend_at_z$q;
        pend_at_c0$d = pend_at_c0$q;
        pend_at_c1$d = pend_at_c1$q;
        pend_at_c2$d = pend_at_c2$q;
        pend_inc0_z$d = pend_inc0_z$q;
        pend_inc0_c0$d = pend_inc0_c0$q;
        pend_inc0_c1$d = pend_inc0_c1$q;
        pend_inc0_c2$d = pend_inc0_c2$q;
        pend_inc1_z$d = pend_inc1_z$q;
        pend_inc1_c0$d = pend_inc1_c0$q;
        pend_inc1_c1$d = pend_inc1_c1$q;
        pend_inc1_c2$d = pend_inc1_c2$q;
        o_valid$d = o_valid$q;
        o_y$d = o_y$q;
        o_xl$d = o_xl$q;
        o_xr$d = o_xr$q;
        o_left_z$d = o_left_z$q;
        o_left_c0$d = o_left_c0$q;
        o_left_c1$d = o_left_c1$q;
        o_left_c2$d = o_left_c2$q;
        o_right_z$d = o_right_z$q;
        o_right_c0$d = o_right_c0$q;
        o_right_c1$d = o_right_c1$q;
        o_right_c2$d = o_right_c2$q;
        maj$clock = clock;
        cur$clock = clock;
        idle = ~busy$q;
        inp$ready = ~busy$q & ~hold;
        accept = inp$valid & ~busy$q & ~hold;
        in_up = inp$walk & clip_y$on;
        height_j = ((height) & 13'h1fff);
        in_j_sign$x = inp$maj_j;
        in_no_rows = inp$maj_count == 32'h0;
        if (clip_y$on) begin
            if (in_up) begin
                if (in_j_sign$neg) begin
                    in_no_rows = 1'b1;
                end
            end
            else if (~in_j_sign$neg & (inp$maj_j >= height_j)) begin
                in_no_rows = 1'b1;
            end
        end
        in_crow = height_j + ~inp$maj_j;
        if (in_up) begin
            in_crow = inp$maj_j;
        end
        in_last = inp$maj_count == 32'h1;
        if (clip_y$on & (in_crow == 32'h0)) begin
            in_last = 1'b1;
        end
        in_short0_none = inp$short0_count == 32'h0;
        start_maj$up = in_up;
        start_maj$r = inp$maj_r;
        start_maj$rho = inp$maj_rho;
        start_maj$d = inp$maj_d;
        start_s0$up = in_up;
        start_s0$r = inp$short0_r;
        start_s0$rho = inp$short0_rho;
        start_s0$d = inp$short0_d;
        start_s1$up = in_up;
        start_s1$r = inp$short1_r;
        start_s1$rho = inp$short1_rho;
        start_s1$d = inp$short1_d;
        j_sign$x = j$q;
        j_next = j$q + 32'h1;
        if (up$q) begin
            j_next = j$q - 32'h1;
        end
        sides$a = cur$x;
        sides$b = maj$x;
        if (maj_left$q) begin
            sides$a = maj$x;
            sides$b = cur$x;
        end
        valid = sides$lt;
        if (clip_y$on & j_sign$neg) begin
            valid = 1'b0;
        end
        free = ~o_valid$q | out$ready;
        emit = walking$q & free;
        step = emit & ~last_r$q;
        if (free) begin
            o_valid$d = 1'b0;
        end
        if (emit) begin
            o_valid$d = valid;
            o_y$d = ((j$q) & 10'h3ff);
            if (maj_left$q) begin
                o_xl$d = maj$x;
                o_xr$d = cur$x - 32'h1;
                o_left_z$d = maj$at_z;
                o_left_c0$d = maj$at_c0;
                o_left_c1$d = maj$at_c1;
                o_left_c2$d = maj$at_c2;
                o_right_z$d = cur$at_z;
                o_right_c0$d = cur$at_c0;
                o_right_c1$d = cur$at_c1;
                o_right_c2$d = cur$at_c2;
            end
            else begin
                o_xl$d = cur$x;
                o_xr$d = maj$x - 32'h1;
                o_left_z$d = cur$at_z;
                o_left_c0$d = cur$at_c0;
                o_left_c1$d = cur$at_c1;
                o_left_c2$d = cur$at_c2;
                o_right_z$d = maj$at_z;
                o_right_c0$d = maj$at_c0;
                o_right_c1$d = maj$at_c1;
                o_right_c2$d = maj$at_c2;
            end
        end
        out$valid = o_valid$q;
        out$y = o_y$q;
        out$xl = o_xl$q;
        out$xr = o_xr$q;
        out$left_z = o_left_z$q;
        out$left_c0 = o_left_c0$q;
        out$left_c1 = o_left_c1$q;
        out$left_c2 = o_left_c2$q;
        out$right_z = o_right_z$q;
        out$right_c0 = o_right_c0$q;
        out$right_c1 = o_right_c1$q;
        out$right_c2 = o_right_c2$q;
        out$ddx_z = ddx_z$q;
        out$ddx_c0 = ddx_c0$q;
        out$ddx_c1 = ddx_c1$q;
        out$ddx_c2 = ddx_c2$q;
        maj$up = up$q;
        maj$load = accept;
        maj$step = step;
        cur$up = up$q;
        cur$load = accept | (step & sw_r$q);
        cur$step = step;
        maj$ld_x = inp$maj_x;
        maj$ld_q = ((inp$maj_q) & 13'h1fff);
        maj$ld_t = start_maj$t;
        maj$ld_a = start_maj$a;
        maj$ld_b = start_maj$b;
        maj$ld_at_z = inp$maj_at_z;
        maj$ld_at_c0 = inp$maj_at_c0;
        maj$ld_at_c1 = inp$maj_at_c1;
        maj$ld_at_c2 = inp$maj_at_c2;
        maj$ld_inc0_z = ((inp$maj_inc0_z) & 36'hfffffffff);
        maj$ld_inc0_c0 = ((inp$maj_inc0_c0) & 32'hffffffff);
        maj$ld_inc0_c1 = ((inp$maj_inc0_c1) & 32'hffffffff);
        maj$ld_inc0_c2 = ((inp$maj_inc0_c2) & 32'hffffffff);
        maj$ld_inc1_z = ((inp$maj_inc1_z) & 36'hfffffffff);
        maj$ld_inc1_c0 = ((inp$maj_inc1_c0) & 32'hffffffff);
        maj$ld_inc1_c1 = ((inp$maj_inc1_c1) & 32'hffffffff);
        maj$ld_inc1_c2 = ((inp$maj_inc1_c2) & 32'hffffffff);
        if (busy$q) begin
            cur$ld_x = pend_x$q;
            cur$ld_q = pend_q$q;
            cur$ld_t = pend_t$q;
            cur$ld_a = pend_a$q;
            cur$ld_b = pend_b$q;
            cur$ld_at_z = pend_at_z$q;
            cur$ld_at_c0 = pend_at_c0$q;
            cur$ld_at_c1 = pend_at_c1$q;
            cur$ld_at_c2 = pend_at_c2$q;
            cur$ld_inc0_z = pend_inc0_z$q;
            cur$ld_inc0_c0 = pend_inc0_c0$q;
            cur$ld_inc0_c1 = pend_inc0_c1$q;
            cur$ld_inc0_c2 = pend_inc0_c2$q;
            cur$ld_inc1_z = pend_inc1_z$q;
            cur$ld_inc1_c0 = pend_inc1_c0$q;
            cur$ld_inc1_c1 = pend_inc1_c1$q;
            cur$ld_inc1_c2 = pend_inc1_c2$q;
        end
        else if (in_short0_none) begin
            cur$ld_x = inp$short1_x;
            cur$ld_q = ((inp$short1_q) & 13'h1fff);
            cur$ld_t = start_s1$t;
            cur$ld_a = start_s1$a;
            cur$ld_b = start_s1$b;
            cur$ld_at_z = inp$short1_at_z;
            cur$ld_at_c0 = inp$short1_at_c0;
            cur$ld_at_c1 = inp$short1_at_c1;
            cur$ld_at_c2 = inp$short1_at_c2;
            cur$ld_inc0_z = ((inp$short1_inc0_z) & 36'hfffffffff);
            cur$ld_inc0_c0 = ((inp$short1_inc0_c0) & 32'hffffffff);
            cur$ld_inc0_c1 = ((inp$short1_inc0_c1) & 32'hffffffff);
            cur$ld_inc0_c2 = ((inp$short1_inc0_c2) & 32'hffffffff);
            cur$ld_inc1_z = ((inp$short1_inc1_z) & 36'hfffffffff);
            cur$ld_inc1_c0 = ((inp$short1_inc1_c0) & 32'hffffffff);
            cur$ld_inc1_c1 = ((inp$short1_inc1_c1) & 32'hffffffff);
            cur$ld_inc1_c2 = ((inp$short1_inc1_c2) & 32'hffffffff);
        end
        else begin
            cur$ld_x = inp$short0_x;
            cur$ld_q = ((inp$short0_q) & 13'h1fff);
            cur$ld_t = start_s0$t;
            cur$ld_a = start_s0$a;
            cur$ld_b = start_s0$b;
            cur$ld_at_z = inp$short0_at_z;
            cur$ld_at_c0 = inp$short0_at_c0;
            cur$ld_at_c1 = inp$short0_at_c1;
            cur$ld_at_c2 = inp$short0_at_c2;
            cur$ld_inc0_z = ((inp$short0_inc0_z) & 36'hfffffffff);
            cur$ld_inc0_c0 = ((inp$short0_inc0_c0) & 32'hffffffff);
            cur$ld_inc0_c1 = ((inp$short0_inc0_c1) & 32'hffffffff);
            cur$ld_inc0_c2 = ((inp$short0_inc0_c2) & 32'hffffffff);
            cur$ld_inc1_z = ((inp$short0_inc1_z) & 36'hfffffffff);
            cur$ld_inc1_c0 = ((inp$short0_inc1_c0) & 32'hffffffff);
            cur$ld_inc1_c1 = ((inp$short0_inc1_c1) & 32'hffffffff);
            cur$ld_inc1_c2 = ((inp$short0_inc1_c2) & 32'hffffffff);
        end
        if (step) begin
            j$d = j_next;
            rem$d = rem$q - 32'h1;
            crow$d = crow$q - 32'h1;
            crem$d = crem$q - 32'h1;
            last_r$d = rem$q == 32'h1;
            if (clip_y$on & (crow$q == 32'h1)) begin
                last_r$d = 1'b1;
            end
            sw_r$d = crem$q == 32'h1;
        end
        if (emit & last_r$q) begin
            walking$d = 1'b0;
        end
        if (busy$q & ~walking$q & free) begin
            busy$d = 1'b0;
        end
        if (accept) begin
            busy$d = 1'b1;
            walking$d = ~in_no_rows;
            up$d = in_up;
            maj_left$d = inp$maj_left;
            j$d = inp$maj_j;
            rem$d = inp$maj_count - 32'h1;
            crow$d = in_crow;
            crem$d = inp$short0_count - 32'h1;
            last_r$d = in_last;
            sw_r$d = inp$short0_count == 32'h1;
            ddx_z$d = inp$ddx_z;
            ddx_c0$d = inp$ddx_c0;
            ddx_c1$d = inp$ddx_c1;
            ddx_c2$d = inp$ddx_c2;
            pend_x$d = inp$short1_x;
            pend_q$d = ((inp$short1_q) & 13'h1fff);
            pend_t$d = start_s1$t;
            pend_a$d = start_s1$a;
            pend_b$d = start_s1$b;
            pend_at_z$d = inp$short1_at_z;
            pend_at_c0$d = inp$short1_at_c0;
            pend_at_c1$d = inp$short1_at_c1;
            pend_at_c2$d = inp$short1_at_c2;
            pend_inc0_z$d = ((inp$short1_inc0_z) & 36'hfffffffff);
            pend_inc0_c0$d = ((inp$short1_inc0_c0) & 32'hffffffff);
            pend_inc0_c1$d = ((inp$short1_inc0_c1) & 32'hffffffff);
            pend_inc0_c2$d = ((inp$short1_inc0_c2) & 32'hffffffff);
            pend_inc1_z$d = ((inp$short1_inc1_z) & 36'hfffffffff);
            pend_inc1_c0$d = ((inp$short1_inc1_c0) & 32'hffffffff);
            pend_inc1_c1$d = ((inp$short1_inc1_c1) & 32'hffffffff);
            pend_inc1_c2$d = ((inp$short1_inc1_c2) & 32'hffffffff);
        end
        free_next = ~busy$q | (~walking$q & free);
        if (accept) begin
            free_next = 1'b0;
        end
    end
    
endmodule // edge_walk


module edge_walk$busy(d,q,clock);
    
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
          
endmodule // edge_walk$busy


module edge_walk$clip_y(on);
    
    // Module arguments
    output reg  on;
    
    // Constant declarations
    localparam  value = 1'b1;
    
    // Update code
    always @(*) begin
        on = value;
    end
    
endmodule // edge_walk$clip_y


module edge_walk$crem(d,q,clock);
    
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
          
endmodule // edge_walk$crem


module edge_walk$crow(d,q,clock);
    
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
          
endmodule // edge_walk$crow


module edge_walk$cur(clock,load,step,up,ld_x,ld_q,ld_t,ld_a,ld_b,ld_at_z,ld_at_c0,ld_at_c1,ld_at_c2,ld_inc0_z,ld_inc0_c0,ld_inc0_c1,ld_inc0_c2,ld_inc1_z,ld_inc1_c0,ld_inc1_c1,ld_inc1_c2,x,at_z,at_c0,at_c1,at_c2);
    
    // Module arguments
    input wire  clock;
    input wire  load;
    input wire  step;
    input wire  up;
    input wire  [12:0] ld_x;
    input wire  [12:0] ld_q;
    input wire  [21:0] ld_t;
    input wire  [21:0] ld_a;
    input wire  [21:0] ld_b;
    input wire  [35:0] ld_at_z;
    input wire  [31:0] ld_at_c0;
    input wire  [31:0] ld_at_c1;
    input wire  [31:0] ld_at_c2;
    input wire  [35:0] ld_inc0_z;
    input wire  [31:0] ld_inc0_c0;
    input wire  [31:0] ld_inc0_c1;
    input wire  [31:0] ld_inc0_c2;
    input wire  [35:0] ld_inc1_z;
    input wire  [31:0] ld_inc1_c0;
    input wire  [31:0] ld_inc1_c1;
    input wire  [31:0] ld_inc1_c2;
    output reg  [12:0] x;
    output reg  [35:0] at_z;
    output reg  [31:0] at_c0;
    output reg  [31:0] at_c1;
    output reg  [31:0] at_c2;
    
    // Stub signals
    reg  [12:0] x_r$d;
    wire  [12:0] x_r$q;
    reg  x_r$clock;
    reg  [12:0] q_r$d;
    wire  [12:0] q_r$q;
    reg  q_r$clock;
    reg  [21:0] t_r$d;
    wire  [21:0] t_r$q;
    reg  t_r$clock;
    reg  [21:0] a_r$d;
    wire  [21:0] a_r$q;
    reg  a_r$clock;
    reg  [21:0] b_r$d;
    wire  [21:0] b_r$q;
    reg  b_r$clock;
    reg  z$clock;
    reg  z$load;
    reg  z$step;
    reg  z$up;
    reg  z$one;
    reg  [35:0] z$ld_at;
    reg  [35:0] z$ld_inc0;
    reg  [35:0] z$ld_inc1;
    wire  [35:0] z$at;
    reg  c0$clock;
    reg  c0$load;
    reg  c0$step;
    reg  c0$up;
    reg  c0$one;
    reg  [31:0] c0$ld_at;
    reg  [31:0] c0$ld_inc0;
    reg  [31:0] c0$ld_inc1;
    wire  [31:0] c0$at;
    reg  c1$clock;
    reg  c1$load;
    reg  c1$step;
    reg  c1$up;
    reg  c1$one;
    reg  [31:0] c1$ld_at;
    reg  [31:0] c1$ld_inc0;
    reg  [31:0] c1$ld_inc1;
    wire  [31:0] c1$at;
    reg  c2$clock;
    reg  c2$load;
    reg  c2$step;
    reg  c2$up;
    reg  c2$one;
    reg  [31:0] c2$ld_at;
    reg  [31:0] c2$ld_inc0;
    reg  [31:0] c2$ld_inc1;
    wire  [31:0] c2$at;
    reg  [21:0] t_sign$x;
    wire  t_sign$neg;
    
    // Local signals
    reg  one;
    reg  [21:0] t_inc;
    reg  [12:0] q_dir;
    reg  one_dir;
    
    // Sub module instances
    edge_walk$cur$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    edge_walk$cur$q_r q_r(
        .d(q_r$d),
        .q(q_r$q),
        .clock(q_r$clock)
    );
    edge_walk$cur$t_r t_r(
        .d(t_r$d),
        .q(t_r$q),
        .clock(t_r$clock)
    );
    edge_walk$cur$a_r a_r(
        .d(a_r$d),
        .q(a_r$q),
        .clock(a_r$clock)
    );
    edge_walk$cur$b_r b_r(
        .d(b_r$d),
        .q(b_r$q),
        .clock(b_r$clock)
    );
    edge_walk$cur$z z(
        .clock(z$clock),
        .load(z$load),
        .step(z$step),
        .up(z$up),
        .one(z$one),
        .ld_at(z$ld_at),
        .ld_inc0(z$ld_inc0),
        .ld_inc1(z$ld_inc1),
        .at(z$at)
    );
    edge_walk$cur$c0 c0(
        .clock(c0$clock),
        .load(c0$load),
        .step(c0$step),
        .up(c0$up),
        .one(c0$one),
        .ld_at(c0$ld_at),
        .ld_inc0(c0$ld_inc0),
        .ld_inc1(c0$ld_inc1),
        .at(c0$at)
    );
    edge_walk$cur$c1 c1(
        .clock(c1$clock),
        .load(c1$load),
        .step(c1$step),
        .up(c1$up),
        .one(c1$one),
        .ld_at(c1$ld_at),
        .ld_inc0(c1$ld_inc0),
        .ld_inc1(c1$ld_inc1),
        .at(c1$at)
    );
    edge_walk$cur$c2 c2(
        .clock(c2$clock),
        .load(c2$load),
        .step(c2$step),
        .up(c2$up),
        .one(c2$one),
        .ld_at(c2$ld_at),
        .ld_inc0(c2$ld_inc0),
        .ld_inc1(c2$ld_inc1),
        .at(c2$at)
    );
    edge_walk$cur$t_sign t_sign(
        .x(t_sign$x),
        .neg(t_sign$neg)
    );
    
    // Update code
    always @(*) begin
        x_r$clock = clock;
        q_r$clock = clock;
        t_r$clock = clock;
        a_r$clock = clock;
        b_r$clock = clock;
        x_r$d = x_r$q;
        q_r$d = q_r$q;
        t_r$d = t_r$q;
        a_r$d = a_r$q;
        b_r$d = b_r$q;
        z$clock = clock;
        c0$clock = clock;
        c1$clock = clock;
        c2$clock = clock;
        t_sign$x = t_r$q;
        one = t_sign$neg;
        t_inc = b_r$q;
        if (one) begin
            t_inc = a_r$q;
        end
        q_dir = q_r$q;
        one_dir = one;
        if (up) begin
            q_dir = ~q_r$q;
            one_dir = ~one;
        end
        if (step) begin
            t_r$d = t_r$q + t_inc;
            x_r$d = x_r$q + q_dir + one_dir;
        end
        if (load) begin
            x_r$d = ld_x;
            q_r$d = ld_q;
            t_r$d = ld_t;
            a_r$d = ld_a;
            b_r$d = ld_b;
        end
        z$load = load;
        z$step = step;
        z$up = up;
        z$one = one;
        z$ld_at = ld_at_z;
        z$ld_inc0 = ld_inc0_z;
        z$ld_inc1 = ld_inc1_z;
        c0$load = load;
        c0$step = step;
        c0$up = up;
        c0$one = one;
        c0$ld_at = ld_at_c0;
        c0$ld_inc0 = ld_inc0_c0;
        c0$ld_inc1 = ld_inc1_c0;
        c1$load = load;
        c1$step = step;
        c1$up = up;
        c1$one = one;
        c1$ld_at = ld_at_c1;
        c1$ld_inc0 = ld_inc0_c1;
        c1$ld_inc1 = ld_inc1_c1;
        c2$load = load;
        c2$step = step;
        c2$up = up;
        c2$one = one;
        c2$ld_at = ld_at_c2;
        c2$ld_inc0 = ld_inc0_c2;
        c2$ld_inc1 = ld_inc1_c2;
        x = x_r$q;
        at_z = z$at;
        at_c0 = c0$at;
        at_c1 = c1$at;
        at_c2 = c2$at;
    end
    
endmodule // edge_walk$cur


module edge_walk$cur$a_r(d,q,clock);
    
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
          
endmodule // edge_walk$cur$a_r


module edge_walk$cur$b_r(d,q,clock);
    
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
          
endmodule // edge_walk$cur$b_r


module edge_walk$cur$c0(clock,load,step,up,one,ld_at,ld_inc0,ld_inc1,at);
    
    // Module arguments
    input wire  clock;
    input wire  load;
    input wire  step;
    input wire  up;
    input wire  one;
    input wire  [31:0] ld_at;
    input wire  [31:0] ld_inc0;
    input wire  [31:0] ld_inc1;
    output reg  [31:0] at;
    
    // Stub signals
    reg  [31:0] at_r$d;
    wire  [31:0] at_r$q;
    reg  at_r$clock;
    reg  [31:0] inc0_r$d;
    wire  [31:0] inc0_r$q;
    reg  inc0_r$clock;
    reg  [31:0] inc1_r$d;
    wire  [31:0] inc1_r$q;
    reg  inc1_r$clock;
    
    // Local signals
    reg  [31:0] inc;
    reg  [31:0] inc_dir;
    
    // Sub module instances
    edge_walk$cur$c0$at_r at_r(
        .d(at_r$d),
        .q(at_r$q),
        .clock(at_r$clock)
    );
    edge_walk$cur$c0$inc0_r inc0_r(
        .d(inc0_r$d),
        .q(inc0_r$q),
        .clock(inc0_r$clock)
    );
    edge_walk$cur$c0$inc1_r inc1_r(
        .d(inc1_r$d),
        .q(inc1_r$q),
        .clock(inc1_r$clock)
    );
    
    // Update code
    always @(*) begin
        at_r$clock = clock;
        inc0_r$clock = clock;
        inc1_r$clock = clock;
        at_r$d = at_r$q;
        inc0_r$d = inc0_r$q;
        inc1_r$d = inc1_r$q;
        inc = inc0_r$q;
        if (one) begin
            inc = inc1_r$q;
        end
        inc_dir = inc;
        if (up) begin
            inc_dir = ~inc;
        end
        if (step) begin
            at_r$d = at_r$q + inc_dir + up;
        end
        if (load) begin
            at_r$d = ld_at;
            inc0_r$d = ld_inc0;
            inc1_r$d = ld_inc1;
        end
        at = at_r$q;
    end
    
endmodule // edge_walk$cur$c0


module edge_walk$cur$c0$at_r(d,q,clock);
    
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
          
endmodule // edge_walk$cur$c0$at_r


module edge_walk$cur$c0$inc0_r(d,q,clock);
    
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
          
endmodule // edge_walk$cur$c0$inc0_r


module edge_walk$cur$c0$inc1_r(d,q,clock);
    
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
          
endmodule // edge_walk$cur$c0$inc1_r


module edge_walk$cur$c1(clock,load,step,up,one,ld_at,ld_inc0,ld_inc1,at);
    
    // Module arguments
    input wire  clock;
    input wire  load;
    input wire  step;
    input wire  up;
    input wire  one;
    input wire  [31:0] ld_at;
    input wire  [31:0] ld_inc0;
    input wire  [31:0] ld_inc1;
    output reg  [31:0] at;
    
    // Stub signals
    reg  [31:0] at_r$d;
    wire  [31:0] at_r$q;
    reg  at_r$clock;
    reg  [31:0] inc0_r$d;
    wire  [31:0] inc0_r$q;
    reg  inc0_r$clock;
    reg  [31:0] inc1_r$d;
    wire  [31:0] inc1_r$q;
    reg  inc1_r$clock;
    
    // Local signals
    reg  [31:0] inc;
    reg  [31:0] inc_dir;
    
    // Sub module instances
    edge_walk$cur$c1$at_r at_r(
        .d(at_r$d),
        .q(at_r$q),
        .clock(at_r$clock)
    );
    edge_walk$cur$c1$inc0_r inc0_r(
        .d(inc0_r$d),
        .q(inc0_r$q),
        .clock(inc0_r$clock)
    );
    edge_walk$cur$c1$inc1_r inc1_r(
        .d(inc1_r$d),
        .q(inc1_r$q),
        .clock(inc1_r$clock)
    );
    
    // Update code
    always @(*) begin
        at_r$clock = clock;
        inc0_r$clock = clock;
        inc1_r$clock = clock;
        at_r$d = at_r$q;
        inc0_r$d = inc0_r$q;
        inc1_r$d = inc1_r$q;
        inc = inc0_r$q;
        if (one) begin
            inc = inc1_r$q;
        end
        inc_dir = inc;
        if (up) begin
            inc_dir = ~inc;
        end
        if (step) begin
            at_r$d = at_r$q + inc_dir + up;
        end
        if (load) begin
            at_r$d = ld_at;
            inc0_r$d = ld_inc0;
            inc1_r$d = ld_inc1;
        end
        at = at_r$q;
    end
    
endmodule // edge_walk$cur$c1


module edge_walk$cur$c1$at_r(d,q,clock);
    
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
          
endmodule // edge_walk$cur$c1$at_r


module edge_walk$cur$c1$inc0_r(d,q,clock);
    
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
          
endmodule // edge_walk$cur$c1$inc0_r


module edge_walk$cur$c1$inc1_r(d,q,clock);
    
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
          
endmodule // edge_walk$cur$c1$inc1_r


module edge_walk$cur$c2(clock,load,step,up,one,ld_at,ld_inc0,ld_inc1,at);
    
    // Module arguments
    input wire  clock;
    input wire  load;
    input wire  step;
    input wire  up;
    input wire  one;
    input wire  [31:0] ld_at;
    input wire  [31:0] ld_inc0;
    input wire  [31:0] ld_inc1;
    output reg  [31:0] at;
    
    // Stub signals
    reg  [31:0] at_r$d;
    wire  [31:0] at_r$q;
    reg  at_r$clock;
    reg  [31:0] inc0_r$d;
    wire  [31:0] inc0_r$q;
    reg  inc0_r$clock;
    reg  [31:0] inc1_r$d;
    wire  [31:0] inc1_r$q;
    reg  inc1_r$clock;
    
    // Local signals
    reg  [31:0] inc;
    reg  [31:0] inc_dir;
    
    // Sub module instances
    edge_walk$cur$c2$at_r at_r(
        .d(at_r$d),
        .q(at_r$q),
        .clock(at_r$clock)
    );
    edge_walk$cur$c2$inc0_r inc0_r(
        .d(inc0_r$d),
        .q(inc0_r$q),
        .clock(inc0_r$clock)
    );
    edge_walk$cur$c2$inc1_r inc1_r(
        .d(inc1_r$d),
        .q(inc1_r$q),
        .clock(inc1_r$clock)
    );
    
    // Update code
    always @(*) begin
        at_r$clock = clock;
        inc0_r$clock = clock;
        inc1_r$clock = clock;
        at_r$d = at_r$q;
        inc0_r$d = inc0_r$q;
        inc1_r$d = inc1_r$q;
        inc = inc0_r$q;
        if (one) begin
            inc = inc1_r$q;
        end
        inc_dir = inc;
        if (up) begin
            inc_dir = ~inc;
        end
        if (step) begin
            at_r$d = at_r$q + inc_dir + up;
        end
        if (load) begin
            at_r$d = ld_at;
            inc0_r$d = ld_inc0;
            inc1_r$d = ld_inc1;
        end
        at = at_r$q;
    end
    
endmodule // edge_walk$cur$c2


module edge_walk$cur$c2$at_r(d,q,clock);
    
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
          
endmodule // edge_walk$cur$c2$at_r


module edge_walk$cur$c2$inc0_r(d,q,clock);
    
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
          
endmodule // edge_walk$cur$c2$inc0_r


module edge_walk$cur$c2$inc1_r(d,q,clock);
    
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
          
endmodule // edge_walk$cur$c2$inc1_r


module edge_walk$cur$q_r(d,q,clock);
    
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
          
endmodule // edge_walk$cur$q_r


module edge_walk$cur$t_r(d,q,clock);
    
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
          
endmodule // edge_walk$cur$t_r


module edge_walk$cur$t_sign(x,neg);
    
    // Module arguments
    input wire  [21:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 22'h200000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // edge_walk$cur$t_sign


module edge_walk$cur$x_r(d,q,clock);
    
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
          
endmodule // edge_walk$cur$x_r


module edge_walk$cur$z(clock,load,step,up,one,ld_at,ld_inc0,ld_inc1,at);
    
    // Module arguments
    input wire  clock;
    input wire  load;
    input wire  step;
    input wire  up;
    input wire  one;
    input wire  [35:0] ld_at;
    input wire  [35:0] ld_inc0;
    input wire  [35:0] ld_inc1;
    output reg  [35:0] at;
    
    // Stub signals
    reg  [35:0] at_r$d;
    wire  [35:0] at_r$q;
    reg  at_r$clock;
    reg  [35:0] inc0_r$d;
    wire  [35:0] inc0_r$q;
    reg  inc0_r$clock;
    reg  [35:0] inc1_r$d;
    wire  [35:0] inc1_r$q;
    reg  inc1_r$clock;
    
    // Local signals
    reg  [35:0] inc;
    reg  [35:0] inc_dir;
    
    // Sub module instances
    edge_walk$cur$z$at_r at_r(
        .d(at_r$d),
        .q(at_r$q),
        .clock(at_r$clock)
    );
    edge_walk$cur$z$inc0_r inc0_r(
        .d(inc0_r$d),
        .q(inc0_r$q),
        .clock(inc0_r$clock)
    );
    edge_walk$cur$z$inc1_r inc1_r(
        .d(inc1_r$d),
        .q(inc1_r$q),
        .clock(inc1_r$clock)
    );
    
    // Update code
    always @(*) begin
        at_r$clock = clock;
        inc0_r$clock = clock;
        inc1_r$clock = clock;
        at_r$d = at_r$q;
        inc0_r$d = inc0_r$q;
        inc1_r$d = inc1_r$q;
        inc = inc0_r$q;
        if (one) begin
            inc = inc1_r$q;
        end
        inc_dir = inc;
        if (up) begin
            inc_dir = ~inc;
        end
        if (step) begin
            at_r$d = at_r$q + inc_dir + up;
        end
        if (load) begin
            at_r$d = ld_at;
            inc0_r$d = ld_inc0;
            inc1_r$d = ld_inc1;
        end
        at = at_r$q;
    end
    
endmodule // edge_walk$cur$z


module edge_walk$cur$z$at_r(d,q,clock);
    
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
          
endmodule // edge_walk$cur$z$at_r


module edge_walk$cur$z$inc0_r(d,q,clock);
    
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
          
endmodule // edge_walk$cur$z$inc0_r


module edge_walk$cur$z$inc1_r(d,q,clock);
    
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
          
endmodule // edge_walk$cur$z$inc1_r


module edge_walk$ddx_c0(d,q,clock);
    
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
          
endmodule // edge_walk$ddx_c0


module edge_walk$ddx_c1(d,q,clock);
    
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
          
endmodule // edge_walk$ddx_c1


module edge_walk$ddx_c2(d,q,clock);
    
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
          
endmodule // edge_walk$ddx_c2


module edge_walk$ddx_z(d,q,clock);
    
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
          
endmodule // edge_walk$ddx_z


module edge_walk$in_j_sign(x,neg);
    
    // Module arguments
    input wire  [12:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 13'b1000000000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // edge_walk$in_j_sign


module edge_walk$j(d,q,clock);
    
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
          
endmodule // edge_walk$j


module edge_walk$j_sign(x,neg);
    
    // Module arguments
    input wire  [12:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 13'b1000000000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // edge_walk$j_sign


module edge_walk$last_r(d,q,clock);
    
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
          
endmodule // edge_walk$last_r


module edge_walk$maj(clock,load,step,up,ld_x,ld_q,ld_t,ld_a,ld_b,ld_at_z,ld_at_c0,ld_at_c1,ld_at_c2,ld_inc0_z,ld_inc0_c0,ld_inc0_c1,ld_inc0_c2,ld_inc1_z,ld_inc1_c0,ld_inc1_c1,ld_inc1_c2,x,at_z,at_c0,at_c1,at_c2);
    
    // Module arguments
    input wire  clock;
    input wire  load;
    input wire  step;
    input wire  up;
    input wire  [12:0] ld_x;
    input wire  [12:0] ld_q;
    input wire  [21:0] ld_t;
    input wire  [21:0] ld_a;
    input wire  [21:0] ld_b;
    input wire  [35:0] ld_at_z;
    input wire  [31:0] ld_at_c0;
    input wire  [31:0] ld_at_c1;
    input wire  [31:0] ld_at_c2;
    input wire  [35:0] ld_inc0_z;
    input wire  [31:0] ld_inc0_c0;
    input wire  [31:0] ld_inc0_c1;
    input wire  [31:0] ld_inc0_c2;
    input wire  [35:0] ld_inc1_z;
    input wire  [31:0] ld_inc1_c0;
    input wire  [31:0] ld_inc1_c1;
    input wire  [31:0] ld_inc1_c2;
    output reg  [12:0] x;
    output reg  [35:0] at_z;
    output reg  [31:0] at_c0;
    output reg  [31:0] at_c1;
    output reg  [31:0] at_c2;
    
    // Stub signals
    reg  [12:0] x_r$d;
    wire  [12:0] x_r$q;
    reg  x_r$clock;
    reg  [12:0] q_r$d;
    wire  [12:0] q_r$q;
    reg  q_r$clock;
    reg  [21:0] t_r$d;
    wire  [21:0] t_r$q;
    reg  t_r$clock;
    reg  [21:0] a_r$d;
    wire  [21:0] a_r$q;
    reg  a_r$clock;
    reg  [21:0] b_r$d;
    wire  [21:0] b_r$q;
    reg  b_r$clock;
    reg  z$clock;
    reg  z$load;
    reg  z$step;
    reg  z$up;
    reg  z$one;
    reg  [35:0] z$ld_at;
    reg  [35:0] z$ld_inc0;
    reg  [35:0] z$ld_inc1;
    wire  [35:0] z$at;
    reg  c0$clock;
    reg  c0$load;
    reg  c0$step;
    reg  c0$up;
    reg  c0$one;
    reg  [31:0] c0$ld_at;
    reg  [31:0] c0$ld_inc0;
    reg  [31:0] c0$ld_inc1;
    wire  [31:0] c0$at;
    reg  c1$clock;
    reg  c1$load;
    reg  c1$step;
    reg  c1$up;
    reg  c1$one;
    reg  [31:0] c1$ld_at;
    reg  [31:0] c1$ld_inc0;
    reg  [31:0] c1$ld_inc1;
    wire  [31:0] c1$at;
    reg  c2$clock;
    reg  c2$load;
    reg  c2$step;
    reg  c2$up;
    reg  c2$one;
    reg  [31:0] c2$ld_at;
    reg  [31:0] c2$ld_inc0;
    reg  [31:0] c2$ld_inc1;
    wire  [31:0] c2$at;
    reg  [21:0] t_sign$x;
    wire  t_sign$neg;
    
    // Local signals
    reg  one;
    reg  [21:0] t_inc;
    reg  [12:0] q_dir;
    reg  one_dir;
    
    // Sub module instances
    edge_walk$maj$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    edge_walk$maj$q_r q_r(
        .d(q_r$d),
        .q(q_r$q),
        .clock(q_r$clock)
    );
    edge_walk$maj$t_r t_r(
        .d(t_r$d),
        .q(t_r$q),
        .clock(t_r$clock)
    );
    edge_walk$maj$a_r a_r(
        .d(a_r$d),
        .q(a_r$q),
        .clock(a_r$clock)
    );
    edge_walk$maj$b_r b_r(
        .d(b_r$d),
        .q(b_r$q),
        .clock(b_r$clock)
    );
    edge_walk$maj$z z(
        .clock(z$clock),
        .load(z$load),
        .step(z$step),
        .up(z$up),
        .one(z$one),
        .ld_at(z$ld_at),
        .ld_inc0(z$ld_inc0),
        .ld_inc1(z$ld_inc1),
        .at(z$at)
    );
    edge_walk$maj$c0 c0(
        .clock(c0$clock),
        .load(c0$load),
        .step(c0$step),
        .up(c0$up),
        .one(c0$one),
        .ld_at(c0$ld_at),
        .ld_inc0(c0$ld_inc0),
        .ld_inc1(c0$ld_inc1),
        .at(c0$at)
    );
    edge_walk$maj$c1 c1(
        .clock(c1$clock),
        .load(c1$load),
        .step(c1$step),
        .up(c1$up),
        .one(c1$one),
        .ld_at(c1$ld_at),
        .ld_inc0(c1$ld_inc0),
        .ld_inc1(c1$ld_inc1),
        .at(c1$at)
    );
    edge_walk$maj$c2 c2(
        .clock(c2$clock),
        .load(c2$load),
        .step(c2$step),
        .up(c2$up),
        .one(c2$one),
        .ld_at(c2$ld_at),
        .ld_inc0(c2$ld_inc0),
        .ld_inc1(c2$ld_inc1),
        .at(c2$at)
    );
    edge_walk$maj$t_sign t_sign(
        .x(t_sign$x),
        .neg(t_sign$neg)
    );
    
    // Update code
    always @(*) begin
        x_r$clock = clock;
        q_r$clock = clock;
        t_r$clock = clock;
        a_r$clock = clock;
        b_r$clock = clock;
        x_r$d = x_r$q;
        q_r$d = q_r$q;
        t_r$d = t_r$q;
        a_r$d = a_r$q;
        b_r$d = b_r$q;
        z$clock = clock;
        c0$clock = clock;
        c1$clock = clock;
        c2$clock = clock;
        t_sign$x = t_r$q;
        one = t_sign$neg;
        t_inc = b_r$q;
        if (one) begin
            t_inc = a_r$q;
        end
        q_dir = q_r$q;
        one_dir = one;
        if (up) begin
            q_dir = ~q_r$q;
            one_dir = ~one;
        end
        if (step) begin
            t_r$d = t_r$q + t_inc;
            x_r$d = x_r$q + q_dir + one_dir;
        end
        if (load) begin
            x_r$d = ld_x;
            q_r$d = ld_q;
            t_r$d = ld_t;
            a_r$d = ld_a;
            b_r$d = ld_b;
        end
        z$load = load;
        z$step = step;
        z$up = up;
        z$one = one;
        z$ld_at = ld_at_z;
        z$ld_inc0 = ld_inc0_z;
        z$ld_inc1 = ld_inc1_z;
        c0$load = load;
        c0$step = step;
        c0$up = up;
        c0$one = one;
        c0$ld_at = ld_at_c0;
        c0$ld_inc0 = ld_inc0_c0;
        c0$ld_inc1 = ld_inc1_c0;
        c1$load = load;
        c1$step = step;
        c1$up = up;
        c1$one = one;
        c1$ld_at = ld_at_c1;
        c1$ld_inc0 = ld_inc0_c1;
        c1$ld_inc1 = ld_inc1_c1;
        c2$load = load;
        c2$step = step;
        c2$up = up;
        c2$one = one;
        c2$ld_at = ld_at_c2;
        c2$ld_inc0 = ld_inc0_c2;
        c2$ld_inc1 = ld_inc1_c2;
        x = x_r$q;
        at_z = z$at;
        at_c0 = c0$at;
        at_c1 = c1$at;
        at_c2 = c2$at;
    end
    
endmodule // edge_walk$maj


module edge_walk$maj$a_r(d,q,clock);
    
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
          
endmodule // edge_walk$maj$a_r


module edge_walk$maj$b_r(d,q,clock);
    
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
          
endmodule // edge_walk$maj$b_r


module edge_walk$maj$c0(clock,load,step,up,one,ld_at,ld_inc0,ld_inc1,at);
    
    // Module arguments
    input wire  clock;
    input wire  load;
    input wire  step;
    input wire  up;
    input wire  one;
    input wire  [31:0] ld_at;
    input wire  [31:0] ld_inc0;
    input wire  [31:0] ld_inc1;
    output reg  [31:0] at;
    
    // Stub signals
    reg  [31:0] at_r$d;
    wire  [31:0] at_r$q;
    reg  at_r$clock;
    reg  [31:0] inc0_r$d;
    wire  [31:0] inc0_r$q;
    reg  inc0_r$clock;
    reg  [31:0] inc1_r$d;
    wire  [31:0] inc1_r$q;
    reg  inc1_r$clock;
    
    // Local signals
    reg  [31:0] inc;
    reg  [31:0] inc_dir;
    
    // Sub module instances
    edge_walk$maj$c0$at_r at_r(
        .d(at_r$d),
        .q(at_r$q),
        .clock(at_r$clock)
    );
    edge_walk$maj$c0$inc0_r inc0_r(
        .d(inc0_r$d),
        .q(inc0_r$q),
        .clock(inc0_r$clock)
    );
    edge_walk$maj$c0$inc1_r inc1_r(
        .d(inc1_r$d),
        .q(inc1_r$q),
        .clock(inc1_r$clock)
    );
    
    // Update code
    always @(*) begin
        at_r$clock = clock;
        inc0_r$clock = clock;
        inc1_r$clock = clock;
        at_r$d = at_r$q;
        inc0_r$d = inc0_r$q;
        inc1_r$d = inc1_r$q;
        inc = inc0_r$q;
        if (one) begin
            inc = inc1_r$q;
        end
        inc_dir = inc;
        if (up) begin
            inc_dir = ~inc;
        end
        if (step) begin
            at_r$d = at_r$q + inc_dir + up;
        end
        if (load) begin
            at_r$d = ld_at;
            inc0_r$d = ld_inc0;
            inc1_r$d = ld_inc1;
        end
        at = at_r$q;
    end
    
endmodule // edge_walk$maj$c0


module edge_walk$maj$c0$at_r(d,q,clock);
    
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
          
endmodule // edge_walk$maj$c0$at_r


module edge_walk$maj$c0$inc0_r(d,q,clock);
    
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
          
endmodule // edge_walk$maj$c0$inc0_r


module edge_walk$maj$c0$inc1_r(d,q,clock);
    
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
          
endmodule // edge_walk$maj$c0$inc1_r


module edge_walk$maj$c1(clock,load,step,up,one,ld_at,ld_inc0,ld_inc1,at);
    
    // Module arguments
    input wire  clock;
    input wire  load;
    input wire  step;
    input wire  up;
    input wire  one;
    input wire  [31:0] ld_at;
    input wire  [31:0] ld_inc0;
    input wire  [31:0] ld_inc1;
    output reg  [31:0] at;
    
    // Stub signals
    reg  [31:0] at_r$d;
    wire  [31:0] at_r$q;
    reg  at_r$clock;
    reg  [31:0] inc0_r$d;
    wire  [31:0] inc0_r$q;
    reg  inc0_r$clock;
    reg  [31:0] inc1_r$d;
    wire  [31:0] inc1_r$q;
    reg  inc1_r$clock;
    
    // Local signals
    reg  [31:0] inc;
    reg  [31:0] inc_dir;
    
    // Sub module instances
    edge_walk$maj$c1$at_r at_r(
        .d(at_r$d),
        .q(at_r$q),
        .clock(at_r$clock)
    );
    edge_walk$maj$c1$inc0_r inc0_r(
        .d(inc0_r$d),
        .q(inc0_r$q),
        .clock(inc0_r$clock)
    );
    edge_walk$maj$c1$inc1_r inc1_r(
        .d(inc1_r$d),
        .q(inc1_r$q),
        .clock(inc1_r$clock)
    );
    
    // Update code
    always @(*) begin
        at_r$clock = clock;
        inc0_r$clock = clock;
        inc1_r$clock = clock;
        at_r$d = at_r$q;
        inc0_r$d = inc0_r$q;
        inc1_r$d = inc1_r$q;
        inc = inc0_r$q;
        if (one) begin
            inc = inc1_r$q;
        end
        inc_dir = inc;
        if (up) begin
            inc_dir = ~inc;
        end
        if (step) begin
            at_r$d = at_r$q + inc_dir + up;
        end
        if (load) begin
            at_r$d = ld_at;
            inc0_r$d = ld_inc0;
            inc1_r$d = ld_inc1;
        end
        at = at_r$q;
    end
    
endmodule // edge_walk$maj$c1


module edge_walk$maj$c1$at_r(d,q,clock);
    
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
          
endmodule // edge_walk$maj$c1$at_r


module edge_walk$maj$c1$inc0_r(d,q,clock);
    
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
          
endmodule // edge_walk$maj$c1$inc0_r


module edge_walk$maj$c1$inc1_r(d,q,clock);
    
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
          
endmodule // edge_walk$maj$c1$inc1_r


module edge_walk$maj$c2(clock,load,step,up,one,ld_at,ld_inc0,ld_inc1,at);
    
    // Module arguments
    input wire  clock;
    input wire  load;
    input wire  step;
    input wire  up;
    input wire  one;
    input wire  [31:0] ld_at;
    input wire  [31:0] ld_inc0;
    input wire  [31:0] ld_inc1;
    output reg  [31:0] at;
    
    // Stub signals
    reg  [31:0] at_r$d;
    wire  [31:0] at_r$q;
    reg  at_r$clock;
    reg  [31:0] inc0_r$d;
    wire  [31:0] inc0_r$q;
    reg  inc0_r$clock;
    reg  [31:0] inc1_r$d;
    wire  [31:0] inc1_r$q;
    reg  inc1_r$clock;
    
    // Local signals
    reg  [31:0] inc;
    reg  [31:0] inc_dir;
    
    // Sub module instances
    edge_walk$maj$c2$at_r at_r(
        .d(at_r$d),
        .q(at_r$q),
        .clock(at_r$clock)
    );
    edge_walk$maj$c2$inc0_r inc0_r(
        .d(inc0_r$d),
        .q(inc0_r$q),
        .clock(inc0_r$clock)
    );
    edge_walk$maj$c2$inc1_r inc1_r(
        .d(inc1_r$d),
        .q(inc1_r$q),
        .clock(inc1_r$clock)
    );
    
    // Update code
    always @(*) begin
        at_r$clock = clock;
        inc0_r$clock = clock;
        inc1_r$clock = clock;
        at_r$d = at_r$q;
        inc0_r$d = inc0_r$q;
        inc1_r$d = inc1_r$q;
        inc = inc0_r$q;
        if (one) begin
            inc = inc1_r$q;
        end
        inc_dir = inc;
        if (up) begin
            inc_dir = ~inc;
        end
        if (step) begin
            at_r$d = at_r$q + inc_dir + up;
        end
        if (load) begin
            at_r$d = ld_at;
            inc0_r$d = ld_inc0;
            inc1_r$d = ld_inc1;
        end
        at = at_r$q;
    end
    
endmodule // edge_walk$maj$c2


module edge_walk$maj$c2$at_r(d,q,clock);
    
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
          
endmodule // edge_walk$maj$c2$at_r


module edge_walk$maj$c2$inc0_r(d,q,clock);
    
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
          
endmodule // edge_walk$maj$c2$inc0_r


module edge_walk$maj$c2$inc1_r(d,q,clock);
    
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
          
endmodule // edge_walk$maj$c2$inc1_r


module edge_walk$maj$q_r(d,q,clock);
    
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
          
endmodule // edge_walk$maj$q_r


module edge_walk$maj$t_r(d,q,clock);
    
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
          
endmodule // edge_walk$maj$t_r


module edge_walk$maj$t_sign(x,neg);
    
    // Module arguments
    input wire  [21:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 22'h200000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // edge_walk$maj$t_sign


module edge_walk$maj$x_r(d,q,clock);
    
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
          
endmodule // edge_walk$maj$x_r


module edge_walk$maj$z(clock,load,step,up,one,ld_at,ld_inc0,ld_inc1,at);
    
    // Module arguments
    input wire  clock;
    input wire  load;
    input wire  step;
    input wire  up;
    input wire  one;
    input wire  [35:0] ld_at;
    input wire  [35:0] ld_inc0;
    input wire  [35:0] ld_inc1;
    output reg  [35:0] at;
    
    // Stub signals
    reg  [35:0] at_r$d;
    wire  [35:0] at_r$q;
    reg  at_r$clock;
    reg  [35:0] inc0_r$d;
    wire  [35:0] inc0_r$q;
    reg  inc0_r$clock;
    reg  [35:0] inc1_r$d;
    wire  [35:0] inc1_r$q;
    reg  inc1_r$clock;
    
    // Local signals
    reg  [35:0] inc;
    reg  [35:0] inc_dir;
    
    // Sub module instances
    edge_walk$maj$z$at_r at_r(
        .d(at_r$d),
        .q(at_r$q),
        .clock(at_r$clock)
    );
    edge_walk$maj$z$inc0_r inc0_r(
        .d(inc0_r$d),
        .q(inc0_r$q),
        .clock(inc0_r$clock)
    );
    edge_walk$maj$z$inc1_r inc1_r(
        .d(inc1_r$d),
        .q(inc1_r$q),
        .clock(inc1_r$clock)
    );
    
    // Update code
    always @(*) begin
        at_r$clock = clock;
        inc0_r$clock = clock;
        inc1_r$clock = clock;
        at_r$d = at_r$q;
        inc0_r$d = inc0_r$q;
        inc1_r$d = inc1_r$q;
        inc = inc0_r$q;
        if (one) begin
            inc = inc1_r$q;
        end
        inc_dir = inc;
        if (up) begin
            inc_dir = ~inc;
        end
        if (step) begin
            at_r$d = at_r$q + inc_dir + up;
        end
        if (load) begin
            at_r$d = ld_at;
            inc0_r$d = ld_inc0;
            inc1_r$d = ld_inc1;
        end
        at = at_r$q;
    end
    
endmodule // edge_walk$maj$z


module edge_walk$maj$z$at_r(d,q,clock);
    
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
          
endmodule // edge_walk$maj$z$at_r


module edge_walk$maj$z$inc0_r(d,q,clock);
    
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
          
endmodule // edge_walk$maj$z$inc0_r


module edge_walk$maj$z$inc1_r(d,q,clock);
    
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
          
endmodule // edge_walk$maj$z$inc1_r


module edge_walk$maj_left(d,q,clock);
    
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
          
endmodule // edge_walk$maj_left


module edge_walk$o_left_c0(d,q,clock);
    
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
          
endmodule // edge_walk$o_left_c0


module edge_walk$o_left_c1(d,q,clock);
    
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
          
endmodule // edge_walk$o_left_c1


module edge_walk$o_left_c2(d,q,clock);
    
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
          
endmodule // edge_walk$o_left_c2


module edge_walk$o_left_z(d,q,clock);
    
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
          
endmodule // edge_walk$o_left_z


module edge_walk$o_right_c0(d,q,clock);
    
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
          
endmodule // edge_walk$o_right_c0


module edge_walk$o_right_c1(d,q,clock);
    
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
          
endmodule // edge_walk$o_right_c1


module edge_walk$o_right_c2(d,q,clock);
    
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
          
endmodule // edge_walk$o_right_c2


module edge_walk$o_right_z(d,q,clock);
    
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
          
endmodule // edge_walk$o_right_z


module edge_walk$o_valid(d,q,clock);
    
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
          
endmodule // edge_walk$o_valid


module edge_walk$o_xl(d,q,clock);
    
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
          
endmodule // edge_walk$o_xl


module edge_walk$o_xr(d,q,clock);
    
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
          
endmodule // edge_walk$o_xr


module edge_walk$o_y(d,q,clock);
    
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
          
endmodule // edge_walk$o_y


module edge_walk$pend_a(d,q,clock);
    
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
          
endmodule // edge_walk$pend_a


module edge_walk$pend_at_c0(d,q,clock);
    
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
          
endmodule // edge_walk$pend_at_c0


module edge_walk$pend_at_c1(d,q,clock);
    
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
          
endmodule // edge_walk$pend_at_c1


module edge_walk$pend_at_c2(d,q,clock);
    
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
          
endmodule // edge_walk$pend_at_c2


module edge_walk$pend_at_z(d,q,clock);
    
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
          
endmodule // edge_walk$pend_at_z


module edge_walk$pend_b(d,q,clock);
    
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
          
endmodule // edge_walk$pend_b


module edge_walk$pend_inc0_c0(d,q,clock);
    
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
          
endmodule // edge_walk$pend_inc0_c0


module edge_walk$pend_inc0_c1(d,q,clock);
    
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
          
endmodule // edge_walk$pend_inc0_c1


module edge_walk$pend_inc0_c2(d,q,clock);
    
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
          
endmodule // edge_walk$pend_inc0_c2


module edge_walk$pend_inc0_z(d,q,clock);
    
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
          
endmodule // edge_walk$pend_inc0_z


module edge_walk$pend_inc1_c0(d,q,clock);
    
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
          
endmodule // edge_walk$pend_inc1_c0


module edge_walk$pend_inc1_c1(d,q,clock);
    
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
          
endmodule // edge_walk$pend_inc1_c1


module edge_walk$pend_inc1_c2(d,q,clock);
    
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
          
endmodule // edge_walk$pend_inc1_c2


module edge_walk$pend_inc1_z(d,q,clock);
    
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
          
endmodule // edge_walk$pend_inc1_z


module edge_walk$pend_q(d,q,clock);
    
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
          
endmodule // edge_walk$pend_q


module edge_walk$pend_t(d,q,clock);
    
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
          
endmodule // edge_walk$pend_t


module edge_walk$pend_x(d,q,clock);
    
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
          
endmodule // edge_walk$pend_x


module edge_walk$rem(d,q,clock);
    
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
          
endmodule // edge_walk$rem


module edge_walk$sides(a,b,lt);
    
    // Module arguments
    input wire  [12:0] a;
    input wire  [12:0] b;
    output reg  lt;
    
    // Constant declarations
    localparam  half = 13'b1000000000000;
    
    // Update code
    always @(*) begin
        lt = (a ^ half) < (b ^ half);
    end
    
endmodule // edge_walk$sides


module edge_walk$start_maj(up,r,rho,d,t,a,b);
    
    // Module arguments
    input wire  up;
    input wire  [20:0] r;
    input wire  [20:0] rho;
    input wire  [20:0] d;
    output reg  [21:0] t;
    output reg  [21:0] a;
    output reg  [21:0] b;
    
    // Local signals
    reg  [21:0] r_w;
    reg  [21:0] rho_w;
    reg  [21:0] d_w;
    reg  [21:0] nr;
    reg  [21:0] nrho;
    reg  [21:0] sum;
    reg  [21:0] carry;
    
    // Update code
    always @(*) begin
        r_w = ((r) & 22'h3fffff);
        rho_w = ((rho) & 22'h3fffff);
        d_w = ((d) & 22'h3fffff);
        a = d_w - rho_w;
        b = ~rho_w + 32'h1;
        nr = ~r_w;
        nrho = ~rho_w;
        sum = d_w ^ nr ^ nrho;
        carry = (d_w & nr) | (d_w & nrho) | (nr & nrho);
        t = r_w - rho_w;
        if (up) begin
            t = sum + ((carry << 32'h1) | 32'h1);
        end
    end
    
endmodule // edge_walk$start_maj


module edge_walk$start_s0(up,r,rho,d,t,a,b);
    
    // Module arguments
    input wire  up;
    input wire  [20:0] r;
    input wire  [20:0] rho;
    input wire  [20:0] d;
    output reg  [21:0] t;
    output reg  [21:0] a;
    output reg  [21:0] b;
    
    // Local signals
    reg  [21:0] r_w;
    reg  [21:0] rho_w;
    reg  [21:0] d_w;
    reg  [21:0] nr;
    reg  [21:0] nrho;
    reg  [21:0] sum;
    reg  [21:0] carry;
    
    // Update code
    always @(*) begin
        r_w = ((r) & 22'h3fffff);
        rho_w = ((rho) & 22'h3fffff);
        d_w = ((d) & 22'h3fffff);
        a = d_w - rho_w;
        b = ~rho_w + 32'h1;
        nr = ~r_w;
        nrho = ~rho_w;
        sum = d_w ^ nr ^ nrho;
        carry = (d_w & nr) | (d_w & nrho) | (nr & nrho);
        t = r_w - rho_w;
        if (up) begin
            t = sum + ((carry << 32'h1) | 32'h1);
        end
    end
    
endmodule // edge_walk$start_s0


module edge_walk$start_s1(up,r,rho,d,t,a,b);
    
    // Module arguments
    input wire  up;
    input wire  [20:0] r;
    input wire  [20:0] rho;
    input wire  [20:0] d;
    output reg  [21:0] t;
    output reg  [21:0] a;
    output reg  [21:0] b;
    
    // Local signals
    reg  [21:0] r_w;
    reg  [21:0] rho_w;
    reg  [21:0] d_w;
    reg  [21:0] nr;
    reg  [21:0] nrho;
    reg  [21:0] sum;
    reg  [21:0] carry;
    
    // Update code
    always @(*) begin
        r_w = ((r) & 22'h3fffff);
        rho_w = ((rho) & 22'h3fffff);
        d_w = ((d) & 22'h3fffff);
        a = d_w - rho_w;
        b = ~rho_w + 32'h1;
        nr = ~r_w;
        nrho = ~rho_w;
        sum = d_w ^ nr ^ nrho;
        carry = (d_w & nr) | (d_w & nrho) | (nr & nrho);
        t = r_w - rho_w;
        if (up) begin
            t = sum + ((carry << 32'h1) | 32'h1);
        end
    end
    
endmodule // edge_walk$start_s1


module edge_walk$sw_r(d,q,clock);
    
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
          
endmodule // edge_walk$sw_r


module edge_walk$up(d,q,clock);
    
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
          
endmodule // edge_walk$up


module edge_walk$walking(d,q,clock);
    
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
          
endmodule // edge_walk$walking
