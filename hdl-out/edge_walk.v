

module edge_walk(clock,height,inp$valid,inp$ready,inp$walk,inp$maj_left,inp$maj_j,inp$maj_count,inp$maj_x,inp$maj_r,inp$maj_q,inp$maj_rho,inp$maj_d,inp$maj_at_z,inp$maj_at_c0,inp$maj_at_c1,inp$maj_at_c2,inp$maj_inc0_z,inp$maj_inc0_c0,inp$maj_inc0_c1,inp$maj_inc0_c2,inp$maj_inc1_z,inp$maj_inc1_c0,inp$maj_inc1_c1,inp$maj_inc1_c2,inp$short0_j,inp$short0_count,inp$short0_x,inp$short0_r,inp$short0_q,inp$short0_rho,inp$short0_d,inp$short0_at_z,inp$short0_at_c0,inp$short0_at_c1,inp$short0_at_c2,inp$short0_inc0_z,inp$short0_inc0_c0,inp$short0_inc0_c1,inp$short0_inc0_c2,inp$short0_inc1_z,inp$short0_inc1_c0,inp$short0_inc1_c1,inp$short0_inc1_c2,inp$short1_j,inp$short1_count,inp$short1_x,inp$short1_r,inp$short1_q,inp$short1_rho,inp$short1_d,inp$short1_at_z,inp$short1_at_c0,inp$short1_at_c1,inp$short1_at_c2,inp$short1_inc0_z,inp$short1_inc0_c0,inp$short1_inc0_c1,inp$short1_inc0_c2,inp$short1_inc1_z,inp$short1_inc1_c0,inp$short1_inc1_c1,inp$short1_inc1_c2,inp$ddx_z,inp$ddx_c0,inp$ddx_c1,inp$ddx_c2,out$valid,out$ready,out$y,out$xl,out$xr,out$left_z,out$left_c0,out$left_c1,out$left_c2,out$right_z,out$right_c0,out$right_c1,out$right_c2,out$ddx_z,out$ddx_c0,out$ddx_c1,out$ddx_c2);
    
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
    
    // Stub signals
    wire  clip_y$on;
    reg  maj$clock;
    reg  maj$load;
    reg  maj$step;
    reg  maj$up;
    reg  [12:0] maj$ld_x;
    reg  [20:0] maj$ld_r;
    reg  [12:0] maj$ld_q;
    reg  [20:0] maj$ld_rho;
    reg  [20:0] maj$ld_d;
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
    reg  [20:0] cur$ld_r;
    reg  [12:0] cur$ld_q;
    reg  [20:0] cur$ld_rho;
    reg  [20:0] cur$ld_d;
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
    reg  [12:0] k$d;
    wire  [12:0] k$q;
    reg  k$clock;
    reg  [12:0] total$d;
    wire  [12:0] total$q;
    reg  total$clock;
    reg  [12:0] c0$d;
    wire  [12:0] c0$q;
    reg  c0$clock;
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
    reg  [20:0] pend_r$d;
    wire  [20:0] pend_r$q;
    reg  pend_r$clock;
    reg  [12:0] pend_q$d;
    wire  [12:0] pend_q$q;
    reg  pend_q$clock;
    reg  [20:0] pend_rho$d;
    wire  [20:0] pend_rho$q;
    reg  pend_rho$clock;
    reg  [20:0] pend_d$d;
    wire  [20:0] pend_d$q;
    reg  pend_d$clock;
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
    reg  [12:0] j_sign$x;
    wire  j_sign$neg;
    reg  [12:0] sides$a;
    reg  [12:0] sides$b;
    wire  sides$lt;
    
    // Local signals
    reg  accept;
    reg  no_rows;
    reg  last;
    reg  advance;
    reg  switch;
    reg  valid;
    reg  [12:0] j_next;
    reg  [12:0] k_next;
    reg  [12:0] height_j;
    
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
        .ld_r(maj$ld_r),
        .ld_q(maj$ld_q),
        .ld_rho(maj$ld_rho),
        .ld_d(maj$ld_d),
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
        .ld_r(cur$ld_r),
        .ld_q(cur$ld_q),
        .ld_rho(cur$ld_rho),
        .ld_d(cur$ld_d),
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
    edge_walk$k k(
        .d(k$d),
        .q(k$q),
        .clock(k$clock)
    );
    edge_walk$total total(
        .d(total$d),
        .q(total$q),
        .clock(total$clock)
    );
    edge_walk$c0 c0(
        .d(c0$d),
        .q(c0$q),
        .clock(c0$clock)
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
    edge_walk$pend_r pend_r(
        .d(pend_r$d),
        .q(pend_r$q),
        .clock(pend_r$clock)
    );
    edge_walk$pend_q pend_q(
        .d(pend_q$d),
        .q(pend_q$q),
        .clock(pend_q$clock)
    );
    edge_walk$pend_rho pend_rho(
        .d(pend_rho$d),
        .q(pend_rho$q),
        .clock(pend_rho$clock)
    );
    edge_walk$pend_d pend_d(
        .d(pend_d$d),
        .q(pend_d$q),
        .clock(pend_d$clock)
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
    edge_walk$j_sign j_sign(
        .x(j_sign$x),
        .neg(j_sign$neg)
    );
    edge_walk$sides sides(
        .a(sides$a),
        .b(sides$b),
        .lt(sides$lt)
    );
    
    // Update code
    always @(*) begin
        busy$clock = clock;
        walking$clock = clock;
        up$clock = clock;
        maj_left$clock = clock;
        j$clock = clock;
        k$clock = clock;
        total$clock = clock;
        c0$clock = clock;
        ddx_z$clock = clock;
        ddx_c0$clock = clock;
        ddx_c1$clock = clock;
        ddx_c2$clock = clock;
        pend_x$clock = clock;
        pend_r$clock = clock;
        pend_q$clock = clock;
        pend_rho$clock = clock;
        pend_d$clock = clock;
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
        busy$d = busy$q;
        walking$d = walking$q;
        up$d = up$q;
        maj_left$d = maj_left$q;
        j$d = j$q;
        k$d = k$q;
        total$d = total$q;
        c0$d = c0$q;
        ddx_z$d = ddx_z$q;
        ddx_c0$d = ddx_c0$q;
        ddx_c1$d = ddx_c1$q;
        ddx_c2$d = ddx_c2$q;
        pend_x$d = pend_x$q;
        pend_r$d = pend_r$q;
        pend_q$d = pend_q$q;
        pend_rho$d = pend_rho$q;
        pend_d$d = pend_d$q;
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
        maj$clock = clock;
        cur$clock = clock;
        inp$ready = ~busy$q;
        accept = inp$valid & ~busy$q;
        j_sign$x = j$q;
        height_j = ((height) & 13'h1fff);
        k_next = k$q + 32'h1;
        j_next = j$q + 32'h1;
        if (up$q) begin
            j_next = j$q - 32'h1;
        end
        last = k_next == total$q;
        if (clip_y$on) begin
            if (up$q) begin
                if (j$q == 32'h0) begin
                    last = 1'b1;
                end
            end
            else if (j_next == height_j) begin
                last = 1'b1;
            end
        end
        no_rows = total$q == 32'h0;
        if (clip_y$on) begin
            if (up$q) begin
                if (j_sign$neg) begin
                    no_rows = 1'b1;
                end
            end
            else if (~j_sign$neg & (j$q >= height_j)) begin
                no_rows = 1'b1;
            end
        end
        out$y = ((j$q) & 10'h3ff);
        out$ddx_z = ddx_z$q;
        out$ddx_c0 = ddx_c0$q;
        out$ddx_c1 = ddx_c1$q;
        out$ddx_c2 = ddx_c2$q;
        if (maj_left$q) begin
            sides$a = maj$x;
            sides$b = cur$x;
            out$xl = maj$x;
            out$xr = cur$x - 32'h1;
            out$left_z = maj$at_z;
            out$left_c0 = maj$at_c0;
            out$left_c1 = maj$at_c1;
            out$left_c2 = maj$at_c2;
            out$right_z = cur$at_z;
            out$right_c0 = cur$at_c0;
            out$right_c1 = cur$at_c1;
            out$right_c2 = cur$at_c2;
        end
        else begin
            sides$a = cur$x;
            sides$b = maj$x;
            out$xl = cur$x;
            out$xr = maj$x - 32'h1;
            out$left_z = cur$at_z;
            out$left_c0 = cur$at_c0;
            out$left_c1 = cur$at_c1;
            out$left_c2 = cur$at_c2;
            out$right_z = maj$at_z;
            out$right_c0 = maj$at_c0;
            out$right_c1 = maj$at_c1;
            out$right_c2 = maj$at_c2;
        end
        valid = busy$q & walking$q & sides$lt;
        if (clip_y$on & j_sign$neg) begin
            valid = 1'b0;
        end
        out$valid = valid;
        advance = busy$q & walking$q & (~valid | out$ready);
        switch = 1'b0;
        if (busy$q & ~walking$q & (c0$q == 32'h0)) begin
            switch = 1'b1;
        end
        if (advance & ~last & (k_next == c0$q)) begin
            switch = 1'b1;
        end
        maj$up = up$q;
        maj$load = accept;
        maj$step = advance & ~last;
        cur$up = up$q;
        cur$load = accept | switch;
        cur$step = advance & ~last;
        maj$ld_x = inp$maj_x;
        maj$ld_r = inp$maj_r;
        maj$ld_q = ((inp$maj_q) & 13'h1fff);
        maj$ld_rho = inp$maj_rho;
        maj$ld_d = inp$maj_d;
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
        if (switch) begin
            cur$ld_x = pend_x$q;
            cur$ld_r = pend_r$q;
            cur$ld_q = pend_q$q;
            cur$ld_rho = pend_rho$q;
            cur$ld_d = pend_d$q;
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
        else begin
            cur$ld_x = inp$short0_x;
            cur$ld_r = inp$short0_r;
            cur$ld_q = ((inp$short0_q) & 13'h1fff);
            cur$ld_rho = inp$short0_rho;
            cur$ld_d = inp$short0_d;
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
        if (accept) begin
            busy$d = 1'b1;
            walking$d = 1'b0;
            up$d = inp$walk & clip_y$on;
            maj_left$d = inp$maj_left;
            j$d = inp$maj_j;
            k$d = 32'h0;
            total$d = inp$maj_count;
            c0$d = inp$short0_count;
            ddx_z$d = inp$ddx_z;
            ddx_c0$d = inp$ddx_c0;
            ddx_c1$d = inp$ddx_c1;
            ddx_c2$d = inp$ddx_c2;
            pend_x$d = inp$short1_x;
            pend_r$d = inp$short1_r;
            pend_q$d = ((inp$short1_q) & 13'h1fff);
            pend_rho$d = inp$short1_rho;
            pend_d$d = inp$short1_d;
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
        if (busy$q & ~walking$q) begin
            walking$d = ~no_rows;
            busy$d = ~no_rows;
        end
        if (advance) begin
            if (last) begin
                busy$d = 1'b0;
                walking$d = 1'b0;
            end
            else begin
                j$d = j_next;
                k$d = k_next;
            end
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


module edge_walk$c0(d,q,clock);
    
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
          
endmodule // edge_walk$c0


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


module edge_walk$cur(clock,load,step,up,ld_x,ld_r,ld_q,ld_rho,ld_d,ld_at_z,ld_at_c0,ld_at_c1,ld_at_c2,ld_inc0_z,ld_inc0_c0,ld_inc0_c1,ld_inc0_c2,ld_inc1_z,ld_inc1_c0,ld_inc1_c1,ld_inc1_c2,x,at_z,at_c0,at_c1,at_c2);
    
    // Module arguments
    input wire  clock;
    input wire  load;
    input wire  step;
    input wire  up;
    input wire  [12:0] ld_x;
    input wire  [20:0] ld_r;
    input wire  [12:0] ld_q;
    input wire  [20:0] ld_rho;
    input wire  [20:0] ld_d;
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
    reg  [20:0] r_r$d;
    wire  [20:0] r_r$q;
    reg  r_r$clock;
    reg  [12:0] q_r$d;
    wire  [12:0] q_r$q;
    reg  q_r$clock;
    reg  [20:0] rho_r$d;
    wire  [20:0] rho_r$q;
    reg  rho_r$clock;
    reg  [20:0] d_r$d;
    wire  [20:0] d_r$q;
    reg  d_r$clock;
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
    
    // Local signals
    reg  one;
    reg  [20:0] r_plus;
    reg  [20:0] r_minus;
    reg  [12:0] x_step;
    
    // Sub module instances
    edge_walk$cur$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    edge_walk$cur$r_r r_r(
        .d(r_r$d),
        .q(r_r$q),
        .clock(r_r$clock)
    );
    edge_walk$cur$q_r q_r(
        .d(q_r$d),
        .q(q_r$q),
        .clock(q_r$clock)
    );
    edge_walk$cur$rho_r rho_r(
        .d(rho_r$d),
        .q(rho_r$q),
        .clock(rho_r$clock)
    );
    edge_walk$cur$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
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
    
    // Update code
    always @(*) begin
        x_r$clock = clock;
        r_r$clock = clock;
        q_r$clock = clock;
        rho_r$clock = clock;
        d_r$clock = clock;
        x_r$d = x_r$q;
        r_r$d = r_r$q;
        q_r$d = q_r$q;
        rho_r$d = rho_r$q;
        d_r$d = d_r$q;
        z$clock = clock;
        c0$clock = clock;
        c1$clock = clock;
        c2$clock = clock;
        r_plus = r_r$q + rho_r$q;
        r_minus = r_r$q - rho_r$q;
        one = r_r$q < rho_r$q;
        if (up) begin
            one = r_plus >= d_r$q;
        end
        x_step = q_r$q + one;
        if (step) begin
            if (up) begin
                x_r$d = x_r$q - x_step;
                r_r$d = r_plus;
                if (one) begin
                    r_r$d = r_plus - d_r$q;
                end
            end
            else begin
                x_r$d = x_r$q + x_step;
                r_r$d = r_minus;
                if (one) begin
                    r_r$d = r_minus + d_r$q;
                end
            end
        end
        if (load) begin
            x_r$d = ld_x;
            r_r$d = ld_r;
            q_r$d = ld_q;
            rho_r$d = ld_rho;
            d_r$d = ld_d;
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
        if (step) begin
            if (up) begin
                at_r$d = at_r$q - inc;
            end
            else begin
                at_r$d = at_r$q + inc;
            end
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
        if (step) begin
            if (up) begin
                at_r$d = at_r$q - inc;
            end
            else begin
                at_r$d = at_r$q + inc;
            end
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
        if (step) begin
            if (up) begin
                at_r$d = at_r$q - inc;
            end
            else begin
                at_r$d = at_r$q + inc;
            end
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


module edge_walk$cur$d_r(d,q,clock);
    
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
          
endmodule // edge_walk$cur$d_r


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


module edge_walk$cur$r_r(d,q,clock);
    
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
          
endmodule // edge_walk$cur$r_r


module edge_walk$cur$rho_r(d,q,clock);
    
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
          
endmodule // edge_walk$cur$rho_r


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
        if (step) begin
            if (up) begin
                at_r$d = at_r$q - inc;
            end
            else begin
                at_r$d = at_r$q + inc;
            end
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


module edge_walk$k(d,q,clock);
    
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
          
endmodule // edge_walk$k


module edge_walk$maj(clock,load,step,up,ld_x,ld_r,ld_q,ld_rho,ld_d,ld_at_z,ld_at_c0,ld_at_c1,ld_at_c2,ld_inc0_z,ld_inc0_c0,ld_inc0_c1,ld_inc0_c2,ld_inc1_z,ld_inc1_c0,ld_inc1_c1,ld_inc1_c2,x,at_z,at_c0,at_c1,at_c2);
    
    // Module arguments
    input wire  clock;
    input wire  load;
    input wire  step;
    input wire  up;
    input wire  [12:0] ld_x;
    input wire  [20:0] ld_r;
    input wire  [12:0] ld_q;
    input wire  [20:0] ld_rho;
    input wire  [20:0] ld_d;
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
    reg  [20:0] r_r$d;
    wire  [20:0] r_r$q;
    reg  r_r$clock;
    reg  [12:0] q_r$d;
    wire  [12:0] q_r$q;
    reg  q_r$clock;
    reg  [20:0] rho_r$d;
    wire  [20:0] rho_r$q;
    reg  rho_r$clock;
    reg  [20:0] d_r$d;
    wire  [20:0] d_r$q;
    reg  d_r$clock;
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
    
    // Local signals
    reg  one;
    reg  [20:0] r_plus;
    reg  [20:0] r_minus;
    reg  [12:0] x_step;
    
    // Sub module instances
    edge_walk$maj$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    edge_walk$maj$r_r r_r(
        .d(r_r$d),
        .q(r_r$q),
        .clock(r_r$clock)
    );
    edge_walk$maj$q_r q_r(
        .d(q_r$d),
        .q(q_r$q),
        .clock(q_r$clock)
    );
    edge_walk$maj$rho_r rho_r(
        .d(rho_r$d),
        .q(rho_r$q),
        .clock(rho_r$clock)
    );
    edge_walk$maj$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
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
    
    // Update code
    always @(*) begin
        x_r$clock = clock;
        r_r$clock = clock;
        q_r$clock = clock;
        rho_r$clock = clock;
        d_r$clock = clock;
        x_r$d = x_r$q;
        r_r$d = r_r$q;
        q_r$d = q_r$q;
        rho_r$d = rho_r$q;
        d_r$d = d_r$q;
        z$clock = clock;
        c0$clock = clock;
        c1$clock = clock;
        c2$clock = clock;
        r_plus = r_r$q + rho_r$q;
        r_minus = r_r$q - rho_r$q;
        one = r_r$q < rho_r$q;
        if (up) begin
            one = r_plus >= d_r$q;
        end
        x_step = q_r$q + one;
        if (step) begin
            if (up) begin
                x_r$d = x_r$q - x_step;
                r_r$d = r_plus;
                if (one) begin
                    r_r$d = r_plus - d_r$q;
                end
            end
            else begin
                x_r$d = x_r$q + x_step;
                r_r$d = r_minus;
                if (one) begin
                    r_r$d = r_minus + d_r$q;
                end
            end
        end
        if (load) begin
            x_r$d = ld_x;
            r_r$d = ld_r;
            q_r$d = ld_q;
            rho_r$d = ld_rho;
            d_r$d = ld_d;
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
        if (step) begin
            if (up) begin
                at_r$d = at_r$q - inc;
            end
            else begin
                at_r$d = at_r$q + inc;
            end
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
        if (step) begin
            if (up) begin
                at_r$d = at_r$q - inc;
            end
            else begin
                at_r$d = at_r$q + inc;
            end
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
        if (step) begin
            if (up) begin
                at_r$d = at_r$q - inc;
            end
            else begin
                at_r$d = at_r$q + inc;
            end
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


module edge_walk$maj$d_r(d,q,clock);
    
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
          
endmodule // edge_walk$maj$d_r


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


module edge_walk$maj$r_r(d,q,clock);
    
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
          
endmodule // edge_walk$maj$r_r


module edge_walk$maj$rho_r(d,q,clock);
    
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
          
endmodule // edge_walk$maj$rho_r


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
        if (step) begin
            if (up) begin
                at_r$d = at_r$q - inc;
            end
            else begin
                at_r$d = at_r$q + inc;
            end
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


module edge_walk$pend_d(d,q,clock);
    
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
          
endmodule // edge_walk$pend_d


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


module edge_walk$pend_r(d,q,clock);
    
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
          
endmodule // edge_walk$pend_r


module edge_walk$pend_rho(d,q,clock);
    
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
          
endmodule // edge_walk$pend_rho


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


module edge_walk$total(d,q,clock);
    
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
          
endmodule // edge_walk$total


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
