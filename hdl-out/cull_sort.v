

module cull_sort(clock,width,height,cull_back,inp$valid,inp$ready,inp$v0_x,inp$v0_y,inp$v0_z,inp$v0_c0,inp$v0_c1,inp$v0_c2,inp$v0_iw,inp$v1_x,inp$v1_y,inp$v1_z,inp$v1_c0,inp$v1_c1,inp$v1_c2,inp$v1_iw,inp$v2_x,inp$v2_y,inp$v2_z,inp$v2_c0,inp$v2_c1,inp$v2_c2,inp$v2_iw,out$valid,out$ready,out$v0_x,out$v0_y,out$v0_z,out$v0_c0,out$v0_c1,out$v0_c2,out$v0_iw,out$v1_x,out$v1_y,out$v1_z,out$v1_c0,out$v1_c1,out$v1_c2,out$v1_iw,out$v2_x,out$v2_y,out$v2_z,out$v2_c0,out$v2_c1,out$v2_c2,out$v2_iw,out$crosses,verdict$valid,verdict$code,verdict$outside,idle);
    
    // Module arguments
    input wire  clock;
    input wire  [10:0] width;
    input wire  [10:0] height;
    input wire  cull_back;
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
    output reg  out$valid;
    input wire  out$ready;
    output reg  [15:0] out$v0_x;
    output reg  [15:0] out$v0_y;
    output reg  [17:0] out$v0_z;
    output reg  [7:0] out$v0_c0;
    output reg  [7:0] out$v0_c1;
    output reg  [7:0] out$v0_c2;
    output reg  [15:0] out$v0_iw;
    output reg  [15:0] out$v1_x;
    output reg  [15:0] out$v1_y;
    output reg  [17:0] out$v1_z;
    output reg  [7:0] out$v1_c0;
    output reg  [7:0] out$v1_c1;
    output reg  [7:0] out$v1_c2;
    output reg  [15:0] out$v1_iw;
    output reg  [15:0] out$v2_x;
    output reg  [15:0] out$v2_y;
    output reg  [17:0] out$v2_z;
    output reg  [7:0] out$v2_c0;
    output reg  [7:0] out$v2_c1;
    output reg  [7:0] out$v2_c2;
    output reg  [15:0] out$v2_iw;
    output reg  [5:0] out$crosses;
    output reg  verdict$valid;
    output reg  [1:0] verdict$code;
    output reg  [5:0] verdict$outside;
    output reg  idle;
    
    // Constant declarations
    localparam  z_max = 18'b1111111111111111;
    localparam  half = 16'h8000;
    localparam  xy_msb = 8'hf;
    localparam  z_msb = 8'h11;
    localparam  area_msb = 8'h21;
    localparam  frac = 8'h4;
    localparam  passed = 2'b0;
    localparam  outside = 2'b1;
    localparam  back_face = 2'b10;
    localparam  zero_area = 2'b11;
    
    // Stub signals
    reg  [15:0] wx$0$x;
    wire  [16:0] wx$0$y;
    reg  [15:0] wx$1$x;
    wire  [16:0] wx$1$y;
    reg  [15:0] wx$2$x;
    wire  [16:0] wx$2$y;
    reg  [15:0] wy$0$x;
    wire  [16:0] wy$0$y;
    reg  [15:0] wy$1$x;
    wire  [16:0] wy$1$y;
    reg  [15:0] wy$2$x;
    wire  [16:0] wy$2$y;
    reg  [15:0] s1x$0$d;
    wire  [15:0] s1x$0$q;
    reg  s1x$0$clock;
    reg  [15:0] s1x$1$d;
    wire  [15:0] s1x$1$q;
    reg  s1x$1$clock;
    reg  [15:0] s1x$2$d;
    wire  [15:0] s1x$2$q;
    reg  s1x$2$clock;
    reg  [15:0] s1y$0$d;
    wire  [15:0] s1y$0$q;
    reg  s1y$0$clock;
    reg  [15:0] s1y$1$d;
    wire  [15:0] s1y$1$q;
    reg  s1y$1$clock;
    reg  [15:0] s1y$2$d;
    wire  [15:0] s1y$2$q;
    reg  s1y$2$clock;
    reg  [17:0] s1z$0$d;
    wire  [17:0] s1z$0$q;
    reg  s1z$0$clock;
    reg  [17:0] s1z$1$d;
    wire  [17:0] s1z$1$q;
    reg  s1z$1$clock;
    reg  [17:0] s1z$2$d;
    wire  [17:0] s1z$2$q;
    reg  s1z$2$clock;
    reg  [7:0] s1c$0$d;
    wire  [7:0] s1c$0$q;
    reg  s1c$0$clock;
    reg  [7:0] s1c$1$d;
    wire  [7:0] s1c$1$q;
    reg  s1c$1$clock;
    reg  [7:0] s1c$2$d;
    wire  [7:0] s1c$2$q;
    reg  s1c$2$clock;
    reg  [7:0] s1c$3$d;
    wire  [7:0] s1c$3$q;
    reg  s1c$3$clock;
    reg  [7:0] s1c$4$d;
    wire  [7:0] s1c$4$q;
    reg  s1c$4$clock;
    reg  [7:0] s1c$5$d;
    wire  [7:0] s1c$5$q;
    reg  s1c$5$clock;
    reg  [7:0] s1c$6$d;
    wire  [7:0] s1c$6$q;
    reg  s1c$6$clock;
    reg  [7:0] s1c$7$d;
    wire  [7:0] s1c$7$q;
    reg  s1c$7$clock;
    reg  [7:0] s1c$8$d;
    wire  [7:0] s1c$8$q;
    reg  s1c$8$clock;
    reg  [15:0] s1iw$0$d;
    wire  [15:0] s1iw$0$q;
    reg  s1iw$0$clock;
    reg  [15:0] s1iw$1$d;
    wire  [15:0] s1iw$1$q;
    reg  s1iw$1$clock;
    reg  [15:0] s1iw$2$d;
    wire  [15:0] s1iw$2$q;
    reg  s1iw$2$clock;
    reg  [16:0] e1x$d;
    wire  [16:0] e1x$q;
    reg  e1x$clock;
    reg  [16:0] e2y$d;
    wire  [16:0] e2y$q;
    reg  e2y$clock;
    reg  [16:0] e2x$d;
    wire  [16:0] e2x$q;
    reg  e2x$clock;
    reg  [16:0] e1y$d;
    wire  [16:0] e1y$q;
    reg  e1y$clock;
    reg  [5:0] outside1$d;
    wire  [5:0] outside1$q;
    reg  outside1$clock;
    reg  [5:0] crosses1$d;
    wire  [5:0] crosses1$q;
    reg  crosses1$clock;
    reg  back1$d;
    wire  back1$q;
    reg  back1$clock;
    reg  full1$d;
    wire  full1$q;
    reg  full1$clock;
    reg  [15:0] s2x$0$d;
    wire  [15:0] s2x$0$q;
    reg  s2x$0$clock;
    reg  [15:0] s2x$1$d;
    wire  [15:0] s2x$1$q;
    reg  s2x$1$clock;
    reg  [15:0] s2x$2$d;
    wire  [15:0] s2x$2$q;
    reg  s2x$2$clock;
    reg  [15:0] s2y$0$d;
    wire  [15:0] s2y$0$q;
    reg  s2y$0$clock;
    reg  [15:0] s2y$1$d;
    wire  [15:0] s2y$1$q;
    reg  s2y$1$clock;
    reg  [15:0] s2y$2$d;
    wire  [15:0] s2y$2$q;
    reg  s2y$2$clock;
    reg  [17:0] s2z$0$d;
    wire  [17:0] s2z$0$q;
    reg  s2z$0$clock;
    reg  [17:0] s2z$1$d;
    wire  [17:0] s2z$1$q;
    reg  s2z$1$clock;
    reg  [17:0] s2z$2$d;
    wire  [17:0] s2z$2$q;
    reg  s2z$2$clock;
    reg  [7:0] s2c$0$d;
    wire  [7:0] s2c$0$q;
    reg  s2c$0$clock;
    reg  [7:0] s2c$1$d;
    wire  [7:0] s2c$1$q;
    reg  s2c$1$clock;
    reg  [7:0] s2c$2$d;
    wire  [7:0] s2c$2$q;
    reg  s2c$2$clock;
    reg  [7:0] s2c$3$d;
    wire  [7:0] s2c$3$q;
    reg  s2c$3$clock;
    reg  [7:0] s2c$4$d;
    wire  [7:0] s2c$4$q;
    reg  s2c$4$clock;
    reg  [7:0] s2c$5$d;
    wire  [7:0] s2c$5$q;
    reg  s2c$5$clock;
    reg  [7:0] s2c$6$d;
    wire  [7:0] s2c$6$q;
    reg  s2c$6$clock;
    reg  [7:0] s2c$7$d;
    wire  [7:0] s2c$7$q;
    reg  s2c$7$clock;
    reg  [7:0] s2c$8$d;
    wire  [7:0] s2c$8$q;
    reg  s2c$8$clock;
    reg  [15:0] s2iw$0$d;
    wire  [15:0] s2iw$0$q;
    reg  s2iw$0$clock;
    reg  [15:0] s2iw$1$d;
    wire  [15:0] s2iw$1$q;
    reg  s2iw$1$clock;
    reg  [15:0] s2iw$2$d;
    wire  [15:0] s2iw$2$q;
    reg  s2iw$2$clock;
    reg  [16:0] area_mul$0$a;
    reg  [16:0] area_mul$0$b;
    wire  [33:0] area_mul$0$p;
    reg  [16:0] area_mul$1$a;
    reg  [16:0] area_mul$1$b;
    wire  [33:0] area_mul$1$p;
    reg  [33:0] prod0$d;
    wire  [33:0] prod0$q;
    reg  prod0$clock;
    reg  [33:0] prod1$d;
    wire  [33:0] prod1$q;
    reg  prod1$clock;
    reg  [5:0] outside2$d;
    wire  [5:0] outside2$q;
    reg  outside2$clock;
    reg  [5:0] crosses2$d;
    wire  [5:0] crosses2$q;
    reg  crosses2$clock;
    reg  back2$d;
    wire  back2$q;
    reg  back2$clock;
    reg  full2$d;
    wire  full2$q;
    reg  full2$clock;
    reg  [15:0] sx$0$d;
    wire  [15:0] sx$0$q;
    reg  sx$0$clock;
    reg  [15:0] sx$1$d;
    wire  [15:0] sx$1$q;
    reg  sx$1$clock;
    reg  [15:0] sx$2$d;
    wire  [15:0] sx$2$q;
    reg  sx$2$clock;
    reg  [15:0] sy$0$d;
    wire  [15:0] sy$0$q;
    reg  sy$0$clock;
    reg  [15:0] sy$1$d;
    wire  [15:0] sy$1$q;
    reg  sy$1$clock;
    reg  [15:0] sy$2$d;
    wire  [15:0] sy$2$q;
    reg  sy$2$clock;
    reg  [17:0] sz$0$d;
    wire  [17:0] sz$0$q;
    reg  sz$0$clock;
    reg  [17:0] sz$1$d;
    wire  [17:0] sz$1$q;
    reg  sz$1$clock;
    reg  [17:0] sz$2$d;
    wire  [17:0] sz$2$q;
    reg  sz$2$clock;
    reg  [7:0] sc$0$d;
    wire  [7:0] sc$0$q;
    reg  sc$0$clock;
    reg  [7:0] sc$1$d;
    wire  [7:0] sc$1$q;
    reg  sc$1$clock;
    reg  [7:0] sc$2$d;
    wire  [7:0] sc$2$q;
    reg  sc$2$clock;
    reg  [7:0] sc$3$d;
    wire  [7:0] sc$3$q;
    reg  sc$3$clock;
    reg  [7:0] sc$4$d;
    wire  [7:0] sc$4$q;
    reg  sc$4$clock;
    reg  [7:0] sc$5$d;
    wire  [7:0] sc$5$q;
    reg  sc$5$clock;
    reg  [7:0] sc$6$d;
    wire  [7:0] sc$6$q;
    reg  sc$6$clock;
    reg  [7:0] sc$7$d;
    wire  [7:0] sc$7$q;
    reg  sc$7$clock;
    reg  [7:0] sc$8$d;
    wire  [7:0] sc$8$q;
    reg  sc$8$clock;
    reg  [15:0] siw$0$d;
    wire  [15:0] siw$0$q;
    reg  siw$0$clock;
    reg  [15:0] siw$1$d;
    wire  [15:0] siw$1$q;
    reg  siw$1$clock;
    reg  [15:0] siw$2$d;
    wire  [15:0] siw$2$q;
    reg  siw$2$clock;
    reg  [5:0] crosses$d;
    wire  [5:0] crosses$q;
    reg  crosses$clock;
    reg  [1:0] code_r$d;
    wire  [1:0] code_r$q;
    reg  code_r$clock;
    reg  [5:0] outside_r$d;
    wire  [5:0] outside_r$q;
    reg  outside_r$clock;
    reg  full$d;
    wire  full$q;
    reg  full$clock;
    wire  cull$on;
    
    // Local signals
    reg  [15:0] vx$0;
    reg  [15:0] vx$1;
    reg  [15:0] vx$2;
    reg  [15:0] vy$0;
    reg  [15:0] vy$1;
    reg  [15:0] vy$2;
    reg  [17:0] vz$0;
    reg  [17:0] vz$1;
    reg  [17:0] vz$2;
    reg  [7:0] vc$0;
    reg  [7:0] vc$1;
    reg  [7:0] vc$2;
    reg  [7:0] vc$3;
    reg  [7:0] vc$4;
    reg  [7:0] vc$5;
    reg  [7:0] vc$6;
    reg  [7:0] vc$7;
    reg  [7:0] vc$8;
    reg  [15:0] viw$0;
    reg  [15:0] viw$1;
    reg  [15:0] viw$2;
    reg  [5:0] oc$0;
    reg  [5:0] oc$1;
    reg  [5:0] oc$2;
    reg  left$0;
    reg  left$1;
    reg  left$2;
    reg  right_of$0;
    reg  right_of$1;
    reg  right_of$2;
    reg  top$0;
    reg  top$1;
    reg  top$2;
    reg  below$0;
    reg  below$1;
    reg  below$2;
    reg  near$0;
    reg  near$1;
    reg  near$2;
    reg  far$0;
    reg  far$1;
    reg  far$2;
    reg  [15:0] right;
    reg  [15:0] bottom;
    reg  [15:0] key$0;
    reg  [15:0] key$1;
    reg  [15:0] key$2;
    reg  le01;
    reg  le12;
    reg  le02;
    reg  gt01;
    reg  gt12;
    reg  gt02;
    reg  [1:0] rank$0;
    reg  [1:0] rank$1;
    reg  [1:0] rank$2;
    reg  [33:0] area;
    reg  [1:0] code;
    reg  take;
    reg  move1;
    reg  move2;
    reg  leave;
    reg  out_free;
    reg  s2_free;
    reg  s1_free;
    
    // Sub module instances
    cull_sort$wx$0 wx$0(
        .x(wx$0$x),
        .y(wx$0$y)
    );
    cull_sort$wx$1 wx$1(
        .x(wx$1$x),
        .y(wx$1$y)
    );
    cull_sort$wx$2 wx$2(
        .x(wx$2$x),
        .y(wx$2$y)
    );
    cull_sort$wy$0 wy$0(
        .x(wy$0$x),
        .y(wy$0$y)
    );
    cull_sort$wy$1 wy$1(
        .x(wy$1$x),
        .y(wy$1$y)
    );
    cull_sort$wy$2 wy$2(
        .x(wy$2$x),
        .y(wy$2$y)
    );
    cull_sort$s1x$0 s1x$0(
        .d(s1x$0$d),
        .q(s1x$0$q),
        .clock(s1x$0$clock)
    );
    cull_sort$s1x$1 s1x$1(
        .d(s1x$1$d),
        .q(s1x$1$q),
        .clock(s1x$1$clock)
    );
    cull_sort$s1x$2 s1x$2(
        .d(s1x$2$d),
        .q(s1x$2$q),
        .clock(s1x$2$clock)
    );
    cull_sort$s1y$0 s1y$0(
        .d(s1y$0$d),
        .q(s1y$0$q),
        .clock(s1y$0$clock)
    );
    cull_sort$s1y$1 s1y$1(
        .d(s1y$1$d),
        .q(s1y$1$q),
        .clock(s1y$1$clock)
    );
    cull_sort$s1y$2 s1y$2(
        .d(s1y$2$d),
        .q(s1y$2$q),
        .clock(s1y$2$clock)
    );
    cull_sort$s1z$0 s1z$0(
        .d(s1z$0$d),
        .q(s1z$0$q),
        .clock(s1z$0$clock)
    );
    cull_sort$s1z$1 s1z$1(
        .d(s1z$1$d),
        .q(s1z$1$q),
        .clock(s1z$1$clock)
    );
    cull_sort$s1z$2 s1z$2(
        .d(s1z$2$d),
        .q(s1z$2$q),
        .clock(s1z$2$clock)
    );
    cull_sort$s1c$0 s1c$0(
        .d(s1c$0$d),
        .q(s1c$0$q),
        .clock(s1c$0$clock)
    );
    cull_sort$s1c$1 s1c$1(
        .d(s1c$1$d),
        .q(s1c$1$q),
        .clock(s1c$1$clock)
    );
    cull_sort$s1c$2 s1c$2(
        .d(s1c$2$d),
        .q(s1c$2$q),
        .clock(s1c$2$clock)
    );
    cull_sort$s1c$3 s1c$3(
        .d(s1c$3$d),
        .q(s1c$3$q),
        .clock(s1c$3$clock)
    );
    cull_sort$s1c$4 s1c$4(
        .d(s1c$4$d),
        .q(s1c$4$q),
        .clock(s1c$4$clock)
    );
    cull_sort$s1c$5 s1c$5(
        .d(s1c$5$d),
        .q(s1c$5$q),
        .clock(s1c$5$clock)
    );
    cull_sort$s1c$6 s1c$6(
        .d(s1c$6$d),
        .q(s1c$6$q),
        .clock(s1c$6$clock)
    );
    cull_sort$s1c$7 s1c$7(
        .d(s1c$7$d),
        .q(s1c$7$q),
        .clock(s1c$7$clock)
    );
    cull_sort$s1c$8 s1c$8(
        .d(s1c$8$d),
        .q(s1c$8$q),
        .clock(s1c$8$clock)
    );
    cull_sort$s1iw$0 s1iw$0(
        .d(s1iw$0$d),
        .q(s1iw$0$q),
        .clock(s1iw$0$clock)
    );
    cull_sort$s1iw$1 s1iw$1(
        .d(s1iw$1$d),
        .q(s1iw$1$q),
        .clock(s1iw$1$clock)
    );
    cull_sort$s1iw$2 s1iw$2(
        .d(s1iw$2$d),
        .q(s1iw$2$q),
        .clock(s1iw$2$clock)
    );
    cull_sort$e1x e1x(
        .d(e1x$d),
        .q(e1x$q),
        .clock(e1x$clock)
    );
    cull_sort$e2y e2y(
        .d(e2y$d),
        .q(e2y$q),
        .clock(e2y$clock)
    );
    cull_sort$e2x e2x(
        .d(e2x$d),
        .q(e2x$q),
        .clock(e2x$clock)
    );
    cull_sort$e1y e1y(
        .d(e1y$d),
        .q(e1y$q),
        .clock(e1y$clock)
    );
    cull_sort$outside1 outside1(
        .d(outside1$d),
        .q(outside1$q),
        .clock(outside1$clock)
    );
    cull_sort$crosses1 crosses1(
        .d(crosses1$d),
        .q(crosses1$q),
        .clock(crosses1$clock)
    );
    cull_sort$back1 back1(
        .d(back1$d),
        .q(back1$q),
        .clock(back1$clock)
    );
    cull_sort$full1 full1(
        .d(full1$d),
        .q(full1$q),
        .clock(full1$clock)
    );
    cull_sort$s2x$0 s2x$0(
        .d(s2x$0$d),
        .q(s2x$0$q),
        .clock(s2x$0$clock)
    );
    cull_sort$s2x$1 s2x$1(
        .d(s2x$1$d),
        .q(s2x$1$q),
        .clock(s2x$1$clock)
    );
    cull_sort$s2x$2 s2x$2(
        .d(s2x$2$d),
        .q(s2x$2$q),
        .clock(s2x$2$clock)
    );
    cull_sort$s2y$0 s2y$0(
        .d(s2y$0$d),
        .q(s2y$0$q),
        .clock(s2y$0$clock)
    );
    cull_sort$s2y$1 s2y$1(
        .d(s2y$1$d),
        .q(s2y$1$q),
        .clock(s2y$1$clock)
    );
    cull_sort$s2y$2 s2y$2(
        .d(s2y$2$d),
        .q(s2y$2$q),
        .clock(s2y$2$clock)
    );
    cull_sort$s2z$0 s2z$0(
        .d(s2z$0$d),
        .q(s2z$0$q),
        .clock(s2z$0$clock)
    );
    cull_sort$s2z$1 s2z$1(
        .d(s2z$1$d),
        .q(s2z$1$q),
        .clock(s2z$1$clock)
    );
    cull_sort$s2z$2 s2z$2(
        .d(s2z$2$d),
        .q(s2z$2$q),
        .clock(s2z$2$clock)
    );
    cull_sort$s2c$0 s2c$0(
        .d(s2c$0$d),
        .q(s2c$0$q),
        .clock(s2c$0$clock)
    );
    cull_sort$s2c$1 s2c$1(
        .d(s2c$1$d),
        .q(s2c$1$q),
        .clock(s2c$1$clock)
    );
    cull_sort$s2c$2 s2c$2(
        .d(s2c$2$d),
        .q(s2c$2$q),
        .clock(s2c$2$clock)
    );
    cull_sort$s2c$3 s2c$3(
        .d(s2c$3$d),
        .q(s2c$3$q),
        .clock(s2c$3$clock)
    );
    cull_sort$s2c$4 s2c$4(
        .d(s2c$4$d),
        .q(s2c$4$q),
        .clock(s2c$4$clock)
    );
    cull_sort$s2c$5 s2c$5(
        .d(s2c$5$d),
        .q(s2c$5$q),
        .clock(s2c$5$clock)
    );
    cull_sort$s2c$6 s2c$6(
        .d(s2c$6$d),
        .q(s2c$6$q),
        .clock(s2c$6$clock)
    );
    cull_sort$s2c$7 s2c$7(
        .d(s2c$7$d),
        .q(s2c$7$q),
        .clock(s2c$7$clock)
    );
    cull_sort$s2c$8 s2c$8(
        .d(s2c$8$d),
        .q(s2c$8$q),
        .clock(s2c$8$clock)
    );
    cull_sort$s2iw$0 s2iw$0(
        .d(s2iw$0$d),
        .q(s2iw$0$q),
        .clock(s2iw$0$clock)
    );
    cull_sort$s2iw$1 s2iw$1(
        .d(s2iw$1$d),
        .q(s2iw$1$q),
        .clock(s2iw$1$clock)
    );
    cull_sort$s2iw$2 s2iw$2(
        .d(s2iw$2$d),
        .q(s2iw$2$q),
        .clock(s2iw$2$clock)
    );
    cull_sort$area_mul$0 area_mul$0(
        .a(area_mul$0$a),
        .b(area_mul$0$b),
        .p(area_mul$0$p)
    );
    cull_sort$area_mul$1 area_mul$1(
        .a(area_mul$1$a),
        .b(area_mul$1$b),
        .p(area_mul$1$p)
    );
    cull_sort$prod0 prod0(
        .d(prod0$d),
        .q(prod0$q),
        .clock(prod0$clock)
    );
    cull_sort$prod1 prod1(
        .d(prod1$d),
        .q(prod1$q),
        .clock(prod1$clock)
    );
    cull_sort$outside2 outside2(
        .d(outside2$d),
        .q(outside2$q),
        .clock(outside2$clock)
    );
    cull_sort$crosses2 crosses2(
        .d(crosses2$d),
        .q(crosses2$q),
        .clock(crosses2$clock)
    );
    cull_sort$back2 back2(
        .d(back2$d),
        .q(back2$q),
        .clock(back2$clock)
    );
    cull_sort$full2 full2(
        .d(full2$d),
        .q(full2$q),
        .clock(full2$clock)
    );
    cull_sort$sx$0 sx$0(
        .d(sx$0$d),
        .q(sx$0$q),
        .clock(sx$0$clock)
    );
    cull_sort$sx$1 sx$1(
        .d(sx$1$d),
        .q(sx$1$q),
        .clock(sx$1$clock)
    );
    cull_sort$sx$2 sx$2(
        .d(sx$2$d),
        .q(sx$2$q),
        .clock(sx$2$clock)
    );
    cull_sort$sy$0 sy$0(
        .d(sy$0$d),
        .q(sy$0$q),
        .clock(sy$0$clock)
    );
    cull_sort$sy$1 sy$1(
        .d(sy$1$d),
        .q(sy$1$q),
        .clock(sy$1$clock)
    );
    cull_sort$sy$2 sy$2(
        .d(sy$2$d),
        .q(sy$2$q),
        .clock(sy$2$clock)
    );
    cull_sort$sz$0 sz$0(
        .d(sz$0$d),
        .q(sz$0$q),
        .clock(sz$0$clock)
    );
    cull_sort$sz$1 sz$1(
        .d(sz$1$d),
        .q(sz$1$q),
        .clock(sz$1$clock)
    );
    cull_sort$sz$2 sz$2(
        .d(sz$2$d),
        .q(sz$2$q),
        .clock(sz$2$clock)
    );
    cull_sort$sc$0 sc$0(
        .d(sc$0$d),
        .q(sc$0$q),
        .clock(sc$0$clock)
    );
    cull_sort$sc$1 sc$1(
        .d(sc$1$d),
        .q(sc$1$q),
        .clock(sc$1$clock)
    );
    cull_sort$sc$2 sc$2(
        .d(sc$2$d),
        .q(sc$2$q),
        .clock(sc$2$clock)
    );
    cull_sort$sc$3 sc$3(
        .d(sc$3$d),
        .q(sc$3$q),
        .clock(sc$3$clock)
    );
    cull_sort$sc$4 sc$4(
        .d(sc$4$d),
        .q(sc$4$q),
        .clock(sc$4$clock)
    );
    cull_sort$sc$5 sc$5(
        .d(sc$5$d),
        .q(sc$5$q),
        .clock(sc$5$clock)
    );
    cull_sort$sc$6 sc$6(
        .d(sc$6$d),
        .q(sc$6$q),
        .clock(sc$6$clock)
    );
    cull_sort$sc$7 sc$7(
        .d(sc$7$d),
        .q(sc$7$q),
        .clock(sc$7$clock)
    );
    cull_sort$sc$8 sc$8(
        .d(sc$8$d),
        .q(sc$8$q),
        .clock(sc$8$clock)
    );
    cull_sort$siw$0 siw$0(
        .d(siw$0$d),
        .q(siw$0$q),
        .clock(siw$0$clock)
    );
    cull_sort$siw$1 siw$1(
        .d(siw$1$d),
        .q(siw$1$q),
        .clock(siw$1$clock)
    );
    cull_sort$siw$2 siw$2(
        .d(siw$2$d),
        .q(siw$2$q),
        .clock(siw$2$clock)
    );
    cull_sort$crosses crosses(
        .d(crosses$d),
        .q(crosses$q),
        .clock(crosses$clock)
    );
    cull_sort$code_r code_r(
        .d(code_r$d),
        .q(code_r$q),
        .clock(code_r$clock)
    );
    cull_sort$outside_r outside_r(
        .d(outside_r$d),
        .q(outside_r$q),
        .clock(outside_r$clock)
    );
    cull_sort$full full(
        .d(full$d),
        .q(full$q),
        .clock(full$clock)
    );
    cull_sort$cull cull(
        .on(cull$on)
    );
    
    // Update code
    always @(*) begin
        e1x$clock = clock;
        e2y$clock = clock;
        e2x$clock = clock;
        e1y$clock = clock;
        outside1$clock = clock;
        crosses1$clock = clock;
        back1$clock = clock;
        full1$clock = clock;
        prod0$clock = clock;
        prod1$clock = clock;
        outside2$clock = clock;
        crosses2$clock = clock;
        back2$clock = clock;
        full2$clock = clock;
        crosses$clock = clock;
        code_r$clock = clock;
        outside_r$clock = clock;
        full$clock = clock;
        e1x$d = e1x$q;
        e2y$d = e2y$q;
        e2x$d = e2x$q;
        e1y$d = e1y$q;
        outside1$d = outside1$q;
        crosses1$d = crosses1$q;
        back1$d = back1$q;
        full1$d = full1$q;
        prod0$d = prod0$q;
        prod1$d = prod1$q;
        outside2$d = outside2$q;
        crosses2$d = crosses2$q;
        back2$d = back2$q;
        full2$d = full2$q;
        crosses$d = crosses$q;
        code_r$d = code_r$q;
        outside_r$d = outside_r$q;
        full$d = full$q;
        s1x$0$clock = clock;
        s1x$0$d = s1x$0$q;
        s1y$0$clock = clock;
        s1y$0$d = s1y$0$q;
        s1z$0$clock = clock;
        s1z$0$d = s1z$0$q;
        s1iw$0$clock = clock;
        s1iw$0$d = s1iw$0$q;
        s2x$0$clock = clock;
        s2x$0$d = s2x$0$q;
        s2y$0$clock = clock;
        s2y$0$d = s2y$0$q;
        s2z$0$clock = clock;
        s2z$0$d = s2z$0$q;
        s2iw$0$clock = clock;
        s2iw$0$d = s2iw$0$q;
        sx$0$clock = clock;
        sx$0$d = sx$0$q;
        sy$0$clock = clock;
        sy$0$d = sy$0$q;
        sz$0$clock = clock;
        sz$0$d = sz$0$q;
        siw$0$clock = clock;
        siw$0$d = siw$0$q;
        s1x$1$clock = clock;
        s1x$1$d = s1x$1$q;
        s1y$1$clock = clock;
        s1y$1$d = s1y$1$q;
        s1z$1$clock = clock;
        s1z$1$d = s1z$1$q;
        s1iw$1$clock = clock;
        s1iw$1$d = s1iw$1$q;
        s2x$1$clock = clock;
        s2x$1$d = s2x$1$q;
        s2y$1$clock = clock;
        s2y$1$d = s2y$1$q;
        s2z$1$clock = clock;
        s2z$1$d = s2z$1$q;
        s2iw$1$clock = clock;
        s2iw$1$d = s2iw$1$q;
        sx$1$clock = clock;
        sx$1$d = sx$1$q;
        sy$1$clock = clock;
        sy$1$d = sy$1$q;
        sz$1$clock = clock;
        sz$1$d = sz$1$q;
        siw$1$clock = clock;
        siw$1$d = siw$1$q;
        s1x$2$clock = clock;
        s1x$2$d = s1x$2$q;
        s1y$2$clock = clock;
        s1y$2$d = s1y$2$q;
        s1z$2$clock = clock;
        s1z$2$d = s1z$2$q;
        s1iw$2$clock = clock;
        s1iw$2$d = s1iw$2$q;
        s2x$2$clock = clock;
        s2x$2$d = s2x$2$q;
        s2y$2$clock = clock;
        s2y$2$d = s2y$2$q;
        s2z$2$clock = clock;
        s2z$2$d = s2z$2$q;
        s2iw$2$clock = clock;
        s2iw$2$d = s2iw$2$q;
        sx$2$clock = clock;
        sx$2$d = sx$2$q;
        sy$2$clock = clock;
        sy$2$d = sy$2$q;
        sz$2$clock = clock;
        sz$2$d = sz$2$q;
        siw$2$clock = clock;
        siw$2$d = siw$2$q;
        s1c$0$clock = clock;
        s1c$0$d = s1c$0$q;
        s2c$0$clock = clock;
        s2c$0$d = s2c$0$q;
        sc$0$clock = clock;
        sc$0$d = sc$0$q;
        s1c$1$clock = clock;
        s1c$1$d = s1c$1$q;
        s2c$1$clock = clock;
        s2c$1$d = s2c$1$q;
        sc$1$clock = clock;
        sc$1$d = sc$1$q;
        s1c$2$clock = clock;
        s1c$2$d = s1c$2$q;
        s2c$2$clock = clock;
        s2c$2$d = s2c$2$q;
        sc$2$clock = clock;
        sc$2$d = sc$2$q;
        s1c$3$clock = clock;
        s1c$3$d = s1c$3$q;
        s2c$3$clock = clock;
        s2c$3$d = s2c$3$q;
        sc$3$clock = clock;
        sc$3$d = sc$3$q;
        s1c$4$clock = clock;
        s1c$4$d = s1c$4$q;
        s2c$4$clock = clock;
        s2c$4$d = s2c$4$q;
        sc$4$clock = clock;
        sc$4$d = sc$4$q;
        s1c$5$clock = clock;
        s1c$5$d = s1c$5$q;
        s2c$5$clock = clock;
        s2c$5$d = s2c$5$q;
        sc$5$clock = clock;
        sc$5$d = sc$5$q;
        s1c$6$clock = clock;
        s1c$6$d = s1c$6$q;
        s2c$6$clock = clock;
        s2c$6$d = s2c$6$q;
        sc$6$clock = clock;
        sc$6$d = sc$6$q;
        s1c$7$clock = clock;
        s1c$7$d = s1c$7$q;
        s2c$7$clock = clock;
        s2c$7$d = s2c$7$q;
        sc$7$clock = clock;
        sc$7$d = sc$7$q;
        s1c$8$clock = clock;
        s1c$8$d = s1c$8$q;
        s2c$8$clock = clock;
        s2c$8$d = s2c$8$q;
        sc$8$clock = clock;
        sc$8$d = sc$8$q;
        vx$0 = inp$v0_x;
        vy$0 = inp$v0_y;
        vz$0 = inp$v0_z;
        vc$0 = inp$v0_c0;
        vc$1 = inp$v0_c1;
        vc$2 = inp$v0_c2;
        viw$0 = inp$v0_iw;
        vx$1 = inp$v1_x;
        vy$1 = inp$v1_y;
        vz$1 = inp$v1_z;
        vc$3 = inp$v1_c0;
        vc$4 = inp$v1_c1;
        vc$5 = inp$v1_c2;
        viw$1 = inp$v1_iw;
        vx$2 = inp$v2_x;
        vy$2 = inp$v2_y;
        vz$2 = inp$v2_z;
        vc$6 = inp$v2_c0;
        vc$7 = inp$v2_c1;
        vc$8 = inp$v2_c2;
        viw$2 = inp$v2_iw;
        out_free = ~full$q | (code_r$q != passed);
        s2_free = ~full2$q | out_free;
        s1_free = ~full1$q | s2_free;
        leave = full$q & ((code_r$q != passed) | out$ready);
        move2 = full2$q & (out_free | out$ready);
        move1 = full1$q & (s2_free | out$ready);
        inp$ready = s1_free | out$ready;
        take = inp$valid & (s1_free | out$ready);
        if (leave) begin
            full$d = 1'b0;
        end
        if (move2) begin
            full2$d = 1'b0;
            full$d = 1'b1;
        end
        if (move1) begin
            full1$d = 1'b0;
            full2$d = 1'b1;
        end
        if (take) begin
            full1$d = 1'b1;
        end
        idle = ~full1$q & ~full2$q & ~(full$q & (code_r$q == passed));
        right = ((width) & 16'hffff) << frac;
        bottom = ((height) & 16'hffff) << frac;
        left$0 = vx$0[xy_msb];
        right_of$0 = ~left$0 & (vx$0 > right);
        top$0 = vy$0[xy_msb];
        below$0 = ~top$0 & (vy$0 > bottom);
        near$0 = vz$0[z_msb];
        far$0 = ~near$0 & (vz$0 > z_max);
        oc$0 = ((((((((32'h0) & 6'h3f) & ~(1 << (32'h0)) | ((left$0) << (32'h0))) & ~(1 << (32'h1)) | ((right_of$0) << (32'h1))) & ~(1 << (32'h2)) | ((top$0) << (32'h2))) & ~(1 << (32'h3)) | ((below$0) << (32'h3))) & ~(1 << (32'h4)) | ((near$0) << (32'h4))) & ~(1 << (32'h5)) | ((far$0) << (32'h5)));
        left$1 = vx$1[xy_msb];
        right_of$1 = ~left$1 & (vx$1 > right);
        top$1 = vy$1[xy_msb];
        below$1 = ~top$1 & (vy$1 > bottom);
        near$1 = vz$1[z_msb];
        far$1 = ~near$1 & (vz$1 > z_max);
        oc$1 = ((((((((32'h0) & 6'h3f) & ~(1 << (32'h0)) | ((left$1) << (32'h0))) & ~(1 << (32'h1)) | ((right_of$1) << (32'h1))) & ~(1 << (32'h2)) | ((top$1) << (32'h2))) & ~(1 << (32'h3)) | ((below$1) << (32'h3))) & ~(1 << (32'h4)) | ((near$1) << (32'h4))) & ~(1 << (32'h5)) | ((far$1) << (32'h5)));
        left$2 = vx$2[xy_msb];
        right_of$2 = ~left$2 & (vx$2 > right);
        top$2 = vy$2[xy_msb];
        below$2 = ~top$2 & (vy$2 > bottom);
        near$2 = vz$2[z_msb];
        far$2 = ~near$2 & (vz$2 > z_max);
        oc$2 = ((((((((32'h0) & 6'h3f) & ~(1 << (32'h0)) | ((left$2) << (32'h0))) & ~(1 << (32'h1)) | ((right_of$2) << (32'h1))) & ~(1 << (32'h2)) | ((top$2) << (32'h2))) & ~(1 << (32'h3)) | ((below$2) << (32'h3))) & ~(1 << (32'h4)) | ((near$2) << (32'h4))) & ~(1 << (32'h5)) | ((far$2) << (32'h5)));
        wx$0$x = vx$0;
        wy$0$x = vy$0;
        wx$1$x = vx$1;
        wy$1$x = vy$1;
        wx$2$x = vx$2;
        wy$2$x = vy$2;
        key$0 = vy$0 ^ half;
        key$1 = vy$1 ^ half;
        key$2 = vy$2 ^ half;
        le01 = key$0 <= key$1;
        le12 = key$1 <= key$2;
        le02 = key$0 <= key$2;
        gt01 = ~le01;
        gt12 = ~le12;
        gt02 = ~le02;
        rank$0 = ((32'h0) & 2'h3) + gt01 + gt02;
        rank$1 = ((32'h0) & 2'h3) + le01 + gt12;
        rank$2 = ((32'h0) & 2'h3) + le02 + le12;
        if (take) begin
            e1x$d = wx$1$y - wx$0$y;
            e2y$d = wy$2$y - wy$0$y;
            e2x$d = wx$2$y - wx$0$y;
            e1y$d = wy$1$y - wy$0$y;
            outside1$d = oc$0 & oc$1 & oc$2;
            crosses1$d = oc$0 | oc$1 | oc$2;
            back1$d = cull_back;
            if (rank$0 == 0) begin
                s1x$0$d = vx$0;
                s1y$0$d = vy$0;
                s1z$0$d = vz$0;
                s1iw$0$d = viw$0;
                s1c$0$d = vc$0;
                s1c$1$d = vc$1;
                s1c$2$d = vc$2;
            end
            if (rank$1 == 0) begin
                s1x$0$d = vx$1;
                s1y$0$d = vy$1;
                s1z$0$d = vz$1;
                s1iw$0$d = viw$1;
                s1c$0$d = vc$3;
                s1c$1$d = vc$4;
                s1c$2$d = vc$5;
            end
            if (rank$2 == 0) begin
                s1x$0$d = vx$2;
                s1y$0$d = vy$2;
                s1z$0$d = vz$2;
                s1iw$0$d = viw$2;
                s1c$0$d = vc$6;
                s1c$1$d = vc$7;
                s1c$2$d = vc$8;
            end
            if (rank$0 == 1) begin
                s1x$1$d = vx$0;
                s1y$1$d = vy$0;
                s1z$1$d = vz$0;
                s1iw$1$d = viw$0;
                s1c$3$d = vc$0;
                s1c$4$d = vc$1;
                s1c$5$d = vc$2;
            end
            if (rank$1 == 1) begin
                s1x$1$d = vx$1;
                s1y$1$d = vy$1;
                s1z$1$d = vz$1;
                s1iw$1$d = viw$1;
                s1c$3$d = vc$3;
                s1c$4$d = vc$4;
                s1c$5$d = vc$5;
            end
            if (rank$2 == 1) begin
                s1x$1$d = vx$2;
                s1y$1$d = vy$2;
                s1z$1$d = vz$2;
                s1iw$1$d = viw$2;
                s1c$3$d = vc$6;
                s1c$4$d = vc$7;
                s1c$5$d = vc$8;
            end
            if (rank$0 == 2) begin
                s1x$2$d = vx$0;
                s1y$2$d = vy$0;
                s1z$2$d = vz$0;
                s1iw$2$d = viw$0;
                s1c$6$d = vc$0;
                s1c$7$d = vc$1;
                s1c$8$d = vc$2;
            end
            if (rank$1 == 2) begin
                s1x$2$d = vx$1;
                s1y$2$d = vy$1;
                s1z$2$d = vz$1;
                s1iw$2$d = viw$1;
                s1c$6$d = vc$3;
                s1c$7$d = vc$4;
                s1c$8$d = vc$5;
            end
            if (rank$2 == 2) begin
                s1x$2$d = vx$2;
                s1y$2$d = vy$2;
                s1z$2$d = vz$2;
                s1iw$2$d = viw$2;
                s1c$6$d = vc$6;
                s1c$7$d = vc$7;
                s1c$8$d = vc$8;
            end
        end
        area_mul$0$a = e1x$q;
        area_mul$0$b = e2y$q;
        area_mul$1$a = e2x$q;
        area_mul$1$b = e1y$q;
        if (move1) begin
            prod0$d = area_mul$0$p;
            prod1$d = area_mul$1$p;
            outside2$d = outside1$q;
            crosses2$d = crosses1$q;
            back2$d = back1$q;
            s2x$0$d = s1x$0$q;
            s2y$0$d = s1y$0$q;
            s2z$0$d = s1z$0$q;
            s2iw$0$d = s1iw$0$q;
            s2x$1$d = s1x$1$q;
            s2y$1$d = s1y$1$q;
            s2z$1$d = s1z$1$q;
            s2iw$1$d = s1iw$1$q;
            s2x$2$d = s1x$2$q;
            s2y$2$d = s1y$2$q;
            s2z$2$d = s1z$2$q;
            s2iw$2$d = s1iw$2$q;
            s2c$0$d = s1c$0$q;
            s2c$1$d = s1c$1$q;
            s2c$2$d = s1c$2$q;
            s2c$3$d = s1c$3$q;
            s2c$4$d = s1c$4$q;
            s2c$5$d = s1c$5$q;
            s2c$6$d = s1c$6$q;
            s2c$7$d = s1c$7$q;
            s2c$8$d = s1c$8$q;
        end
        area = prod0$q - prod1$q;
        code = passed;
        if (cull$on) begin
            if (back2$q & ~area[area_msb]) begin
                code = back_face;
            end
            if (prod0$q == prod1$q) begin
                code = zero_area;
            end
            if (|outside2$q) begin
                code = outside;
            end
        end
        if (move2) begin
            code_r$d = code;
            crosses$d = crosses2$q;
            outside_r$d = outside2$q;
            sx$0$d = s2x$0$q;
            sy$0$d = s2y$0$q;
            sz$0$d = s2z$0$q;
            siw$0$d = s2iw$0$q;
            sx$1$d = s2x$1$q;
            sy$1$d = s2y$1$q;
            sz$1$d = s2z$1$q;
            siw$1$d = s2iw$1$q;
            sx$2$d = s2x$2$q;
            sy$2$d = s2y$2$q;
            sz$2$d = s2z$2$q;
            siw$2$d = s2iw$2$q;
            sc$0$d = s2c$0$q;
            sc$1$d = s2c$1$q;
            sc$2$d = s2c$2$q;
            sc$3$d = s2c$3$q;
            sc$4$d = s2c$4$q;
            sc$5$d = s2c$5$q;
            sc$6$d = s2c$6$q;
            sc$7$d = s2c$7$q;
            sc$8$d = s2c$8$q;
        end
        out$valid = full$q & (code_r$q == passed);
        verdict$valid = leave;
        verdict$code = code_r$q;
        verdict$outside = outside_r$q;
        out$crosses = crosses$q;
        out$v0_x = sx$0$q;
        out$v0_y = sy$0$q;
        out$v0_z = sz$0$q;
        out$v0_c0 = sc$0$q;
        out$v0_c1 = sc$1$q;
        out$v0_c2 = sc$2$q;
        out$v0_iw = siw$0$q;
        out$v1_x = sx$1$q;
        out$v1_y = sy$1$q;
        out$v1_z = sz$1$q;
        out$v1_c0 = sc$3$q;
        out$v1_c1 = sc$4$q;
        out$v1_c2 = sc$5$q;
        out$v1_iw = siw$1$q;
        out$v2_x = sx$2$q;
        out$v2_y = sy$2$q;
        out$v2_z = sz$2$q;
        out$v2_c0 = sc$6$q;
        out$v2_c1 = sc$7$q;
        out$v2_c2 = sc$8$q;
        out$v2_iw = siw$2$q;
    end
    
endmodule // cull_sort


module cull_sort$area_mul$0(a,b,p);
    
    // Module arguments
    input wire  [16:0] a;
    input wire  [16:0] b;
    output reg  [33:0] p;
    
    // Update code (custom)
    // p = low 34 bits of a * b, both signed: a signed 34-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // cull_sort$area_mul$0


module cull_sort$area_mul$1(a,b,p);
    
    // Module arguments
    input wire  [16:0] a;
    input wire  [16:0] b;
    output reg  [33:0] p;
    
    // Update code (custom)
    // p = low 34 bits of a * b, both signed: a signed 34-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // cull_sort$area_mul$1


module cull_sort$back1(d,q,clock);
    
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
          
endmodule // cull_sort$back1


module cull_sort$back2(d,q,clock);
    
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
          
endmodule // cull_sort$back2


module cull_sort$code_r(d,q,clock);
    
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
          
endmodule // cull_sort$code_r


module cull_sort$crosses(d,q,clock);
    
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
          
endmodule // cull_sort$crosses


module cull_sort$crosses1(d,q,clock);
    
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
          
endmodule // cull_sort$crosses1


module cull_sort$crosses2(d,q,clock);
    
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
          
endmodule // cull_sort$crosses2


module cull_sort$cull(on);
    
    // Module arguments
    output reg  on;
    
    // Constant declarations
    localparam  value = 1'b1;
    
    // Update code
    always @(*) begin
        on = value;
    end
    
endmodule // cull_sort$cull


module cull_sort$e1x(d,q,clock);
    
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
          
endmodule // cull_sort$e1x


module cull_sort$e1y(d,q,clock);
    
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
          
endmodule // cull_sort$e1y


module cull_sort$e2x(d,q,clock);
    
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
          
endmodule // cull_sort$e2x


module cull_sort$e2y(d,q,clock);
    
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
          
endmodule // cull_sort$e2y


module cull_sort$full(d,q,clock);
    
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
          
endmodule // cull_sort$full


module cull_sort$full1(d,q,clock);
    
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
          
endmodule // cull_sort$full1


module cull_sort$full2(d,q,clock);
    
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
          
endmodule // cull_sort$full2


module cull_sort$outside1(d,q,clock);
    
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
          
endmodule // cull_sort$outside1


module cull_sort$outside2(d,q,clock);
    
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
          
endmodule // cull_sort$outside2


module cull_sort$outside_r(d,q,clock);
    
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
          
endmodule // cull_sort$outside_r


module cull_sort$prod0(d,q,clock);
    
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
          
endmodule // cull_sort$prod0


module cull_sort$prod1(d,q,clock);
    
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
          
endmodule // cull_sort$prod1


module cull_sort$s1c$0(d,q,clock);
    
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
          
endmodule // cull_sort$s1c$0


module cull_sort$s1c$1(d,q,clock);
    
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
          
endmodule // cull_sort$s1c$1


module cull_sort$s1c$2(d,q,clock);
    
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
          
endmodule // cull_sort$s1c$2


module cull_sort$s1c$3(d,q,clock);
    
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
          
endmodule // cull_sort$s1c$3


module cull_sort$s1c$4(d,q,clock);
    
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
          
endmodule // cull_sort$s1c$4


module cull_sort$s1c$5(d,q,clock);
    
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
          
endmodule // cull_sort$s1c$5


module cull_sort$s1c$6(d,q,clock);
    
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
          
endmodule // cull_sort$s1c$6


module cull_sort$s1c$7(d,q,clock);
    
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
          
endmodule // cull_sort$s1c$7


module cull_sort$s1c$8(d,q,clock);
    
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
          
endmodule // cull_sort$s1c$8


module cull_sort$s1iw$0(d,q,clock);
    
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
          
endmodule // cull_sort$s1iw$0


module cull_sort$s1iw$1(d,q,clock);
    
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
          
endmodule // cull_sort$s1iw$1


module cull_sort$s1iw$2(d,q,clock);
    
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
          
endmodule // cull_sort$s1iw$2


module cull_sort$s1x$0(d,q,clock);
    
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
          
endmodule // cull_sort$s1x$0


module cull_sort$s1x$1(d,q,clock);
    
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
          
endmodule // cull_sort$s1x$1


module cull_sort$s1x$2(d,q,clock);
    
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
          
endmodule // cull_sort$s1x$2


module cull_sort$s1y$0(d,q,clock);
    
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
          
endmodule // cull_sort$s1y$0


module cull_sort$s1y$1(d,q,clock);
    
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
          
endmodule // cull_sort$s1y$1


module cull_sort$s1y$2(d,q,clock);
    
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
          
endmodule // cull_sort$s1y$2


module cull_sort$s1z$0(d,q,clock);
    
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
          
endmodule // cull_sort$s1z$0


module cull_sort$s1z$1(d,q,clock);
    
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
          
endmodule // cull_sort$s1z$1


module cull_sort$s1z$2(d,q,clock);
    
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
          
endmodule // cull_sort$s1z$2


module cull_sort$s2c$0(d,q,clock);
    
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
          
endmodule // cull_sort$s2c$0


module cull_sort$s2c$1(d,q,clock);
    
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
          
endmodule // cull_sort$s2c$1


module cull_sort$s2c$2(d,q,clock);
    
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
          
endmodule // cull_sort$s2c$2


module cull_sort$s2c$3(d,q,clock);
    
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
          
endmodule // cull_sort$s2c$3


module cull_sort$s2c$4(d,q,clock);
    
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
          
endmodule // cull_sort$s2c$4


module cull_sort$s2c$5(d,q,clock);
    
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
          
endmodule // cull_sort$s2c$5


module cull_sort$s2c$6(d,q,clock);
    
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
          
endmodule // cull_sort$s2c$6


module cull_sort$s2c$7(d,q,clock);
    
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
          
endmodule // cull_sort$s2c$7


module cull_sort$s2c$8(d,q,clock);
    
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
          
endmodule // cull_sort$s2c$8


module cull_sort$s2iw$0(d,q,clock);
    
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
          
endmodule // cull_sort$s2iw$0


module cull_sort$s2iw$1(d,q,clock);
    
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
          
endmodule // cull_sort$s2iw$1


module cull_sort$s2iw$2(d,q,clock);
    
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
          
endmodule // cull_sort$s2iw$2


module cull_sort$s2x$0(d,q,clock);
    
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
          
endmodule // cull_sort$s2x$0


module cull_sort$s2x$1(d,q,clock);
    
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
          
endmodule // cull_sort$s2x$1


module cull_sort$s2x$2(d,q,clock);
    
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
          
endmodule // cull_sort$s2x$2


module cull_sort$s2y$0(d,q,clock);
    
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
          
endmodule // cull_sort$s2y$0


module cull_sort$s2y$1(d,q,clock);
    
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
          
endmodule // cull_sort$s2y$1


module cull_sort$s2y$2(d,q,clock);
    
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
          
endmodule // cull_sort$s2y$2


module cull_sort$s2z$0(d,q,clock);
    
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
          
endmodule // cull_sort$s2z$0


module cull_sort$s2z$1(d,q,clock);
    
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
          
endmodule // cull_sort$s2z$1


module cull_sort$s2z$2(d,q,clock);
    
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
          
endmodule // cull_sort$s2z$2


module cull_sort$sc$0(d,q,clock);
    
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
          
endmodule // cull_sort$sc$0


module cull_sort$sc$1(d,q,clock);
    
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
          
endmodule // cull_sort$sc$1


module cull_sort$sc$2(d,q,clock);
    
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
          
endmodule // cull_sort$sc$2


module cull_sort$sc$3(d,q,clock);
    
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
          
endmodule // cull_sort$sc$3


module cull_sort$sc$4(d,q,clock);
    
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
          
endmodule // cull_sort$sc$4


module cull_sort$sc$5(d,q,clock);
    
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
          
endmodule // cull_sort$sc$5


module cull_sort$sc$6(d,q,clock);
    
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
          
endmodule // cull_sort$sc$6


module cull_sort$sc$7(d,q,clock);
    
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
          
endmodule // cull_sort$sc$7


module cull_sort$sc$8(d,q,clock);
    
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
          
endmodule // cull_sort$sc$8


module cull_sort$siw$0(d,q,clock);
    
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
          
endmodule // cull_sort$siw$0


module cull_sort$siw$1(d,q,clock);
    
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
          
endmodule // cull_sort$siw$1


module cull_sort$siw$2(d,q,clock);
    
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
          
endmodule // cull_sort$siw$2


module cull_sort$sx$0(d,q,clock);
    
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
          
endmodule // cull_sort$sx$0


module cull_sort$sx$1(d,q,clock);
    
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
          
endmodule // cull_sort$sx$1


module cull_sort$sx$2(d,q,clock);
    
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
          
endmodule // cull_sort$sx$2


module cull_sort$sy$0(d,q,clock);
    
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
          
endmodule // cull_sort$sy$0


module cull_sort$sy$1(d,q,clock);
    
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
          
endmodule // cull_sort$sy$1


module cull_sort$sy$2(d,q,clock);
    
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
          
endmodule // cull_sort$sy$2


module cull_sort$sz$0(d,q,clock);
    
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
          
endmodule // cull_sort$sz$0


module cull_sort$sz$1(d,q,clock);
    
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
          
endmodule // cull_sort$sz$1


module cull_sort$sz$2(d,q,clock);
    
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
          
endmodule // cull_sort$sz$2


module cull_sort$wx$0(x,y);
    
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
    
endmodule // cull_sort$wx$0


module cull_sort$wx$1(x,y);
    
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
    
endmodule // cull_sort$wx$1


module cull_sort$wx$2(x,y);
    
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
    
endmodule // cull_sort$wx$2


module cull_sort$wy$0(x,y);
    
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
    
endmodule // cull_sort$wy$0


module cull_sort$wy$1(x,y);
    
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
    
endmodule // cull_sort$wy$1


module cull_sort$wy$2(x,y);
    
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
    
endmodule // cull_sort$wy$2
