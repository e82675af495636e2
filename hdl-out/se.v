

module se(clock,valid,xl,xr,za,zb,ra,rb,ga,gb,ba,bb,oz0,oz1,oz2,oz3,ready,oz_rd,oz_addr,wr,wr_addr,nz0,nz1,nz2,nz3,r0,r1,r2,r3,g0,g1,g2,g3,b0,b1,b2,b3,we0,we1,we2,we3);
    
    // Module arguments
    input wire  clock;
    input wire  valid;
    input wire  [12:0] xl;
    input wire  [12:0] xr;
    input wire  [39:0] za;
    input wire  [39:0] zb;
    input wire  [31:0] ra;
    input wire  [31:0] rb;
    input wire  [31:0] ga;
    input wire  [31:0] gb;
    input wire  [31:0] ba;
    input wire  [31:0] bb;
    input wire  [23:0] oz0;
    input wire  [23:0] oz1;
    input wire  [23:0] oz2;
    input wire  [23:0] oz3;
    output reg  ready;
    output reg  oz_rd;
    output reg  [3:0] oz_addr;
    output reg  wr;
    output reg  [3:0] wr_addr;
    output reg  [23:0] nz0;
    output reg  [23:0] nz1;
    output reg  [23:0] nz2;
    output reg  [23:0] nz3;
    output reg  [15:0] r0;
    output reg  [15:0] r1;
    output reg  [15:0] r2;
    output reg  [15:0] r3;
    output reg  [15:0] g0;
    output reg  [15:0] g1;
    output reg  [15:0] g2;
    output reg  [15:0] g3;
    output reg  [15:0] b0;
    output reg  [15:0] b1;
    output reg  [15:0] b2;
    output reg  [15:0] b3;
    output reg  we0;
    output reg  we1;
    output reg  we2;
    output reg  we3;
    
    // Constant declarations
    localparam  k_head = 9'b10001000;
    localparam  k_m1 = 9'b101001;
    localparam  k_m2 = 9'b1001001;
    localparam  k_m3 = 9'b1101001;
    localparam  k_t0 = 9'b10000;
    localparam  k_t1 = 9'b111000;
    localparam  k_t2 = 9'b1011000;
    localparam  k_t3 = 9'b1111000;
    localparam  k_q = 9'b10000;
    localparam  k_dq = 5'b10000;
    localparam  k_zext = 8'h19;
    localparam  k_cext = 8'h11;
    localparam  k_win = 8'h8;
    localparam  k_zlast = 8'h1f;
    localparam  k_clast = 8'h17;
    localparam  k_we = 8'h20;
    localparam  k_lo = 13'b1000000000000;
    localparam  k_hi = 13'b1000000111111;
    localparam  k_sign = 13'b1000000000000;
    localparam  k_xl = 11'b0;
    localparam  k_xr = 11'b1000000;
    localparam  k_zamsb = 40'h8000000000;
    localparam  k_camsb = 32'h80000000;
    
    // Stub signals
    reg  [8:0] h$d;
    wire  [8:0] h$q;
    reg  h$clock;
    reg  [7:0] sc$d;
    wire  [7:0] sc$q;
    reg  sc$clock;
    reg  [1:0] att$d;
    wire  [1:0] att$q;
    reg  att$clock;
    reg  [4:0] dc$d;
    wire  [4:0] dc$q;
    reg  dc$clock;
    reg  dgo$d;
    wire  dgo$q;
    reg  dgo$clock;
    reg  [5:0] ml$d;
    wire  [5:0] ml$q;
    reg  ml$clock;
    reg  [5:0] mr$d;
    wire  [5:0] mr$q;
    reg  mr$clock;
    reg  hit$d;
    wire  hit$q;
    reg  hit$clock;
    reg  [39:0] ach_z$d;
    wire  [39:0] ach_z$q;
    reg  ach_z$clock;
    reg  [39:0] bch_z$d;
    wire  [39:0] bch_z$q;
    reg  bch_z$clock;
    reg  [31:0] ach_r$d;
    wire  [31:0] ach_r$q;
    reg  ach_r$clock;
    reg  [31:0] bch_r$d;
    wire  [31:0] bch_r$q;
    reg  bch_r$clock;
    reg  [31:0] ach_g$d;
    wire  [31:0] ach_g$q;
    reg  ach_g$clock;
    reg  [31:0] bch_g$d;
    wire  [31:0] bch_g$q;
    reg  bch_g$clock;
    reg  [31:0] ach_b$d;
    wire  [31:0] ach_b$q;
    reg  ach_b$clock;
    reg  [31:0] bch_b$d;
    wire  [31:0] bch_b$q;
    reg  bch_b$clock;
    reg  mul_l$clock;
    reg  [10:0] mul_l$x;
    reg  mul_l$a;
    reg  mul_l$b;
    reg  mul_l$first;
    reg  mul_l$rnd;
    wire  mul_l$e;
    reg  mul_r$clock;
    reg  [10:0] mul_r$x;
    reg  mul_r$a;
    reg  mul_r$b;
    reg  mul_r$first;
    reg  mul_r$rnd;
    wire  mul_r$e;
    reg  interp$clock;
    reg  interp$e0;
    reg  interp$e1;
    reg  interp$half;
    reg  interp$ext;
    wire  [63:0] interp$px;
    reg  [5:0] ept$xl;
    reg  [5:0] ept$xr;
    wire  [63:0] ept$px;
    reg  zc$0$clock;
    reg  zc$0$first;
    reg  zc$0$nz;
    reg  zc$0$oz;
    wire  zc$0$closer;
    reg  zc$1$clock;
    reg  zc$1$first;
    reg  zc$1$nz;
    reg  zc$1$oz;
    wire  zc$1$closer;
    reg  zc$2$clock;
    reg  zc$2$first;
    reg  zc$2$nz;
    reg  zc$2$oz;
    wire  zc$2$closer;
    reg  zc$3$clock;
    reg  zc$3$first;
    reg  zc$3$nz;
    reg  zc$3$oz;
    wire  zc$3$closer;
    reg  zc$4$clock;
    reg  zc$4$first;
    reg  zc$4$nz;
    reg  zc$4$oz;
    wire  zc$4$closer;
    reg  zc$5$clock;
    reg  zc$5$first;
    reg  zc$5$nz;
    reg  zc$5$oz;
    wire  zc$5$closer;
    reg  zc$6$clock;
    reg  zc$6$first;
    reg  zc$6$nz;
    reg  zc$6$oz;
    wire  zc$6$closer;
    reg  zc$7$clock;
    reg  zc$7$first;
    reg  zc$7$nz;
    reg  zc$7$oz;
    wire  zc$7$closer;
    reg  zc$8$clock;
    reg  zc$8$first;
    reg  zc$8$nz;
    reg  zc$8$oz;
    wire  zc$8$closer;
    reg  zc$9$clock;
    reg  zc$9$first;
    reg  zc$9$nz;
    reg  zc$9$oz;
    wire  zc$9$closer;
    reg  zc$10$clock;
    reg  zc$10$first;
    reg  zc$10$nz;
    reg  zc$10$oz;
    wire  zc$10$closer;
    reg  zc$11$clock;
    reg  zc$11$first;
    reg  zc$11$nz;
    reg  zc$11$oz;
    wire  zc$11$closer;
    reg  zc$12$clock;
    reg  zc$12$first;
    reg  zc$12$nz;
    reg  zc$12$oz;
    wire  zc$12$closer;
    reg  zc$13$clock;
    reg  zc$13$first;
    reg  zc$13$nz;
    reg  zc$13$oz;
    wire  zc$13$closer;
    reg  zc$14$clock;
    reg  zc$14$first;
    reg  zc$14$nz;
    reg  zc$14$oz;
    wire  zc$14$closer;
    reg  zc$15$clock;
    reg  zc$15$first;
    reg  zc$15$nz;
    reg  zc$15$oz;
    wire  zc$15$closer;
    reg  zc$16$clock;
    reg  zc$16$first;
    reg  zc$16$nz;
    reg  zc$16$oz;
    wire  zc$16$closer;
    reg  zc$17$clock;
    reg  zc$17$first;
    reg  zc$17$nz;
    reg  zc$17$oz;
    wire  zc$17$closer;
    reg  zc$18$clock;
    reg  zc$18$first;
    reg  zc$18$nz;
    reg  zc$18$oz;
    wire  zc$18$closer;
    reg  zc$19$clock;
    reg  zc$19$first;
    reg  zc$19$nz;
    reg  zc$19$oz;
    wire  zc$19$closer;
    reg  zc$20$clock;
    reg  zc$20$first;
    reg  zc$20$nz;
    reg  zc$20$oz;
    wire  zc$20$closer;
    reg  zc$21$clock;
    reg  zc$21$first;
    reg  zc$21$nz;
    reg  zc$21$oz;
    wire  zc$21$closer;
    reg  zc$22$clock;
    reg  zc$22$first;
    reg  zc$22$nz;
    reg  zc$22$oz;
    wire  zc$22$closer;
    reg  zc$23$clock;
    reg  zc$23$first;
    reg  zc$23$nz;
    reg  zc$23$oz;
    wire  zc$23$closer;
    reg  zc$24$clock;
    reg  zc$24$first;
    reg  zc$24$nz;
    reg  zc$24$oz;
    wire  zc$24$closer;
    reg  zc$25$clock;
    reg  zc$25$first;
    reg  zc$25$nz;
    reg  zc$25$oz;
    wire  zc$25$closer;
    reg  zc$26$clock;
    reg  zc$26$first;
    reg  zc$26$nz;
    reg  zc$26$oz;
    wire  zc$26$closer;
    reg  zc$27$clock;
    reg  zc$27$first;
    reg  zc$27$nz;
    reg  zc$27$oz;
    wire  zc$27$closer;
    reg  zc$28$clock;
    reg  zc$28$first;
    reg  zc$28$nz;
    reg  zc$28$oz;
    wire  zc$28$closer;
    reg  zc$29$clock;
    reg  zc$29$first;
    reg  zc$29$nz;
    reg  zc$29$oz;
    wire  zc$29$closer;
    reg  zc$30$clock;
    reg  zc$30$first;
    reg  zc$30$nz;
    reg  zc$30$oz;
    wire  zc$30$closer;
    reg  zc$31$clock;
    reg  zc$31$first;
    reg  zc$31$nz;
    reg  zc$31$oz;
    wire  zc$31$closer;
    reg  zc$32$clock;
    reg  zc$32$first;
    reg  zc$32$nz;
    reg  zc$32$oz;
    wire  zc$32$closer;
    reg  zc$33$clock;
    reg  zc$33$first;
    reg  zc$33$nz;
    reg  zc$33$oz;
    wire  zc$33$closer;
    reg  zc$34$clock;
    reg  zc$34$first;
    reg  zc$34$nz;
    reg  zc$34$oz;
    wire  zc$34$closer;
    reg  zc$35$clock;
    reg  zc$35$first;
    reg  zc$35$nz;
    reg  zc$35$oz;
    wire  zc$35$closer;
    reg  zc$36$clock;
    reg  zc$36$first;
    reg  zc$36$nz;
    reg  zc$36$oz;
    wire  zc$36$closer;
    reg  zc$37$clock;
    reg  zc$37$first;
    reg  zc$37$nz;
    reg  zc$37$oz;
    wire  zc$37$closer;
    reg  zc$38$clock;
    reg  zc$38$first;
    reg  zc$38$nz;
    reg  zc$38$oz;
    wire  zc$38$closer;
    reg  zc$39$clock;
    reg  zc$39$first;
    reg  zc$39$nz;
    reg  zc$39$oz;
    wire  zc$39$closer;
    reg  zc$40$clock;
    reg  zc$40$first;
    reg  zc$40$nz;
    reg  zc$40$oz;
    wire  zc$40$closer;
    reg  zc$41$clock;
    reg  zc$41$first;
    reg  zc$41$nz;
    reg  zc$41$oz;
    wire  zc$41$closer;
    reg  zc$42$clock;
    reg  zc$42$first;
    reg  zc$42$nz;
    reg  zc$42$oz;
    wire  zc$42$closer;
    reg  zc$43$clock;
    reg  zc$43$first;
    reg  zc$43$nz;
    reg  zc$43$oz;
    wire  zc$43$closer;
    reg  zc$44$clock;
    reg  zc$44$first;
    reg  zc$44$nz;
    reg  zc$44$oz;
    wire  zc$44$closer;
    reg  zc$45$clock;
    reg  zc$45$first;
    reg  zc$45$nz;
    reg  zc$45$oz;
    wire  zc$45$closer;
    reg  zc$46$clock;
    reg  zc$46$first;
    reg  zc$46$nz;
    reg  zc$46$oz;
    wire  zc$46$closer;
    reg  zc$47$clock;
    reg  zc$47$first;
    reg  zc$47$nz;
    reg  zc$47$oz;
    wire  zc$47$closer;
    reg  zc$48$clock;
    reg  zc$48$first;
    reg  zc$48$nz;
    reg  zc$48$oz;
    wire  zc$48$closer;
    reg  zc$49$clock;
    reg  zc$49$first;
    reg  zc$49$nz;
    reg  zc$49$oz;
    wire  zc$49$closer;
    reg  zc$50$clock;
    reg  zc$50$first;
    reg  zc$50$nz;
    reg  zc$50$oz;
    wire  zc$50$closer;
    reg  zc$51$clock;
    reg  zc$51$first;
    reg  zc$51$nz;
    reg  zc$51$oz;
    wire  zc$51$closer;
    reg  zc$52$clock;
    reg  zc$52$first;
    reg  zc$52$nz;
    reg  zc$52$oz;
    wire  zc$52$closer;
    reg  zc$53$clock;
    reg  zc$53$first;
    reg  zc$53$nz;
    reg  zc$53$oz;
    wire  zc$53$closer;
    reg  zc$54$clock;
    reg  zc$54$first;
    reg  zc$54$nz;
    reg  zc$54$oz;
    wire  zc$54$closer;
    reg  zc$55$clock;
    reg  zc$55$first;
    reg  zc$55$nz;
    reg  zc$55$oz;
    wire  zc$55$closer;
    reg  zc$56$clock;
    reg  zc$56$first;
    reg  zc$56$nz;
    reg  zc$56$oz;
    wire  zc$56$closer;
    reg  zc$57$clock;
    reg  zc$57$first;
    reg  zc$57$nz;
    reg  zc$57$oz;
    wire  zc$57$closer;
    reg  zc$58$clock;
    reg  zc$58$first;
    reg  zc$58$nz;
    reg  zc$58$oz;
    wire  zc$58$closer;
    reg  zc$59$clock;
    reg  zc$59$first;
    reg  zc$59$nz;
    reg  zc$59$oz;
    wire  zc$59$closer;
    reg  zc$60$clock;
    reg  zc$60$first;
    reg  zc$60$nz;
    reg  zc$60$oz;
    wire  zc$60$closer;
    reg  zc$61$clock;
    reg  zc$61$first;
    reg  zc$61$nz;
    reg  zc$61$oz;
    wire  zc$61$closer;
    reg  zc$62$clock;
    reg  zc$62$first;
    reg  zc$62$nz;
    reg  zc$62$oz;
    wire  zc$62$closer;
    reg  zc$63$clock;
    reg  zc$63$first;
    reg  zc$63$nz;
    reg  zc$63$oz;
    wire  zc$63$closer;
    reg  ozm$clock;
    reg  ozm$we;
    reg  [3:0] ozm$group;
    reg  [23:0] ozm$d0;
    reg  [23:0] ozm$d1;
    reg  [23:0] ozm$d2;
    reg  [23:0] ozm$d3;
    reg  [7:0] ozm$plane;
    wire  [63:0] ozm$px;
    reg  nzm$clock;
    reg  nzm$we;
    reg  [7:0] nzm$plane;
    reg  [63:0] nzm$px;
    reg  [3:0] nzm$group;
    wire  [23:0] nzm$w0;
    wire  [23:0] nzm$w1;
    wire  [23:0] nzm$w2;
    wire  [23:0] nzm$w3;
    reg  rm$clock;
    reg  rm$we;
    reg  [7:0] rm$plane;
    reg  [63:0] rm$px;
    reg  [3:0] rm$group;
    wire  [15:0] rm$w0;
    wire  [15:0] rm$w1;
    wire  [15:0] rm$w2;
    wire  [15:0] rm$w3;
    reg  gm$clock;
    reg  gm$we;
    reg  [7:0] gm$plane;
    reg  [63:0] gm$px;
    reg  [3:0] gm$group;
    wire  [15:0] gm$w0;
    wire  [15:0] gm$w1;
    wire  [15:0] gm$w2;
    wire  [15:0] gm$w3;
    reg  bm$clock;
    reg  bm$we;
    reg  [7:0] bm$plane;
    reg  [63:0] bm$px;
    reg  [3:0] bm$group;
    wire  [15:0] bm$w0;
    wire  [15:0] bm$w1;
    wire  [15:0] bm$w2;
    wire  [15:0] bm$w3;
    reg  wes$0$d;
    wire  wes$0$q;
    reg  wes$0$clock;
    reg  wes$1$d;
    wire  wes$1$q;
    reg  wes$1$clock;
    reg  wes$2$d;
    wire  wes$2$q;
    reg  wes$2$clock;
    reg  wes$3$d;
    wire  wes$3$q;
    reg  wes$3$clock;
    reg  wes$4$d;
    wire  wes$4$q;
    reg  wes$4$clock;
    reg  wes$5$d;
    wire  wes$5$q;
    reg  wes$5$clock;
    reg  wes$6$d;
    wire  wes$6$q;
    reg  wes$6$clock;
    reg  wes$7$d;
    wire  wes$7$q;
    reg  wes$7$clock;
    reg  wes$8$d;
    wire  wes$8$q;
    reg  wes$8$clock;
    reg  wes$9$d;
    wire  wes$9$q;
    reg  wes$9$clock;
    reg  wes$10$d;
    wire  wes$10$q;
    reg  wes$10$clock;
    reg  wes$11$d;
    wire  wes$11$q;
    reg  wes$11$clock;
    reg  wes$12$d;
    wire  wes$12$q;
    reg  wes$12$clock;
    reg  wes$13$d;
    wire  wes$13$q;
    reg  wes$13$clock;
    reg  wes$14$d;
    wire  wes$14$q;
    reg  wes$14$clock;
    reg  wes$15$d;
    wire  wes$15$q;
    reg  wes$15$clock;
    reg  wes$16$d;
    wire  wes$16$q;
    reg  wes$16$clock;
    reg  wes$17$d;
    wire  wes$17$q;
    reg  wes$17$clock;
    reg  wes$18$d;
    wire  wes$18$q;
    reg  wes$18$clock;
    reg  wes$19$d;
    wire  wes$19$q;
    reg  wes$19$clock;
    reg  wes$20$d;
    wire  wes$20$q;
    reg  wes$20$clock;
    reg  wes$21$d;
    wire  wes$21$q;
    reg  wes$21$clock;
    reg  wes$22$d;
    wire  wes$22$q;
    reg  wes$22$clock;
    reg  wes$23$d;
    wire  wes$23$q;
    reg  wes$23$clock;
    reg  wes$24$d;
    wire  wes$24$q;
    reg  wes$24$clock;
    reg  wes$25$d;
    wire  wes$25$q;
    reg  wes$25$clock;
    reg  wes$26$d;
    wire  wes$26$q;
    reg  wes$26$clock;
    reg  wes$27$d;
    wire  wes$27$q;
    reg  wes$27$clock;
    reg  wes$28$d;
    wire  wes$28$q;
    reg  wes$28$clock;
    reg  wes$29$d;
    wire  wes$29$q;
    reg  wes$29$clock;
    reg  wes$30$d;
    wire  wes$30$q;
    reg  wes$30$clock;
    reg  wes$31$d;
    wire  wes$31$q;
    reg  wes$31$clock;
    reg  wes$32$d;
    wire  wes$32$q;
    reg  wes$32$clock;
    reg  wes$33$d;
    wire  wes$33$q;
    reg  wes$33$clock;
    reg  wes$34$d;
    wire  wes$34$q;
    reg  wes$34$clock;
    reg  wes$35$d;
    wire  wes$35$q;
    reg  wes$35$clock;
    reg  wes$36$d;
    wire  wes$36$q;
    reg  wes$36$clock;
    reg  wes$37$d;
    wire  wes$37$q;
    reg  wes$37$clock;
    reg  wes$38$d;
    wire  wes$38$q;
    reg  wes$38$clock;
    reg  wes$39$d;
    wire  wes$39$q;
    reg  wes$39$clock;
    reg  wes$40$d;
    wire  wes$40$q;
    reg  wes$40$clock;
    reg  wes$41$d;
    wire  wes$41$q;
    reg  wes$41$clock;
    reg  wes$42$d;
    wire  wes$42$q;
    reg  wes$42$clock;
    reg  wes$43$d;
    wire  wes$43$q;
    reg  wes$43$clock;
    reg  wes$44$d;
    wire  wes$44$q;
    reg  wes$44$clock;
    reg  wes$45$d;
    wire  wes$45$q;
    reg  wes$45$clock;
    reg  wes$46$d;
    wire  wes$46$q;
    reg  wes$46$clock;
    reg  wes$47$d;
    wire  wes$47$q;
    reg  wes$47$clock;
    reg  wes$48$d;
    wire  wes$48$q;
    reg  wes$48$clock;
    reg  wes$49$d;
    wire  wes$49$q;
    reg  wes$49$clock;
    reg  wes$50$d;
    wire  wes$50$q;
    reg  wes$50$clock;
    reg  wes$51$d;
    wire  wes$51$q;
    reg  wes$51$clock;
    reg  wes$52$d;
    wire  wes$52$q;
    reg  wes$52$clock;
    reg  wes$53$d;
    wire  wes$53$q;
    reg  wes$53$clock;
    reg  wes$54$d;
    wire  wes$54$q;
    reg  wes$54$clock;
    reg  wes$55$d;
    wire  wes$55$q;
    reg  wes$55$clock;
    reg  wes$56$d;
    wire  wes$56$q;
    reg  wes$56$clock;
    reg  wes$57$d;
    wire  wes$57$q;
    reg  wes$57$clock;
    reg  wes$58$d;
    wire  wes$58$q;
    reg  wes$58$clock;
    reg  wes$59$d;
    wire  wes$59$q;
    reg  wes$59$clock;
    reg  wes$60$d;
    wire  wes$60$q;
    reg  wes$60$clock;
    reg  wes$61$d;
    wire  wes$61$q;
    reg  wes$61$clock;
    reg  wes$62$d;
    wire  wes$62$q;
    reg  wes$62$clock;
    reg  wes$63$d;
    wire  wes$63$q;
    reg  wes$63$clock;
    
    // Local signals
    reg  rdy;
    reg  accept;
    reg  [12:0] xlb;
    reg  [12:0] xrb;
    reg  ozload;
    reg  mfirst;
    reg  start;
    reg  [1:0] satt;
    reg  isz;
    reg  half;
    reg  ext;
    reg  win;
    reg  send;
    reg  zwin;
    reg  rwin;
    reg  gwin;
    reg  bwin;
    reg  zfirst;
    reg  [7:0] wbit;
    reg  welatch;
    reg  dstart;
    reg  dump;
    reg  [3:0] og;
    reg  [63:0] mask;
    
    // Sub module instances
    se$h h(
        .d(h$d),
        .q(h$q),
        .clock(h$clock)
    );
    se$sc sc(
        .d(sc$d),
        .q(sc$q),
        .clock(sc$clock)
    );
    se$att att(
        .d(att$d),
        .q(att$q),
        .clock(att$clock)
    );
    se$dc dc(
        .d(dc$d),
        .q(dc$q),
        .clock(dc$clock)
    );
    se$dgo dgo(
        .d(dgo$d),
        .q(dgo$q),
        .clock(dgo$clock)
    );
    se$ml ml(
        .d(ml$d),
        .q(ml$q),
        .clock(ml$clock)
    );
    se$mr mr(
        .d(mr$d),
        .q(mr$q),
        .clock(mr$clock)
    );
    se$hit hit(
        .d(hit$d),
        .q(hit$q),
        .clock(hit$clock)
    );
    se$ach_z ach_z(
        .d(ach_z$d),
        .q(ach_z$q),
        .clock(ach_z$clock)
    );
    se$bch_z bch_z(
        .d(bch_z$d),
        .q(bch_z$q),
        .clock(bch_z$clock)
    );
    se$ach_r ach_r(
        .d(ach_r$d),
        .q(ach_r$q),
        .clock(ach_r$clock)
    );
    se$bch_r bch_r(
        .d(bch_r$d),
        .q(bch_r$q),
        .clock(bch_r$clock)
    );
    se$ach_g ach_g(
        .d(ach_g$d),
        .q(ach_g$q),
        .clock(ach_g$clock)
    );
    se$bch_g bch_g(
        .d(bch_g$d),
        .q(bch_g$q),
        .clock(bch_g$clock)
    );
    se$ach_b ach_b(
        .d(ach_b$d),
        .q(ach_b$q),
        .clock(ach_b$clock)
    );
    se$bch_b bch_b(
        .d(bch_b$d),
        .q(bch_b$q),
        .clock(bch_b$clock)
    );
    se$mul_l mul_l(
        .clock(mul_l$clock),
        .x(mul_l$x),
        .a(mul_l$a),
        .b(mul_l$b),
        .first(mul_l$first),
        .rnd(mul_l$rnd),
        .e(mul_l$e)
    );
    se$mul_r mul_r(
        .clock(mul_r$clock),
        .x(mul_r$x),
        .a(mul_r$a),
        .b(mul_r$b),
        .first(mul_r$first),
        .rnd(mul_r$rnd),
        .e(mul_r$e)
    );
    se$interp interp(
        .clock(interp$clock),
        .e0(interp$e0),
        .e1(interp$e1),
        .half(interp$half),
        .ext(interp$ext),
        .px(interp$px)
    );
    se$ept ept(
        .xl(ept$xl),
        .xr(ept$xr),
        .px(ept$px)
    );
    se$zc$0 zc$0(
        .clock(zc$0$clock),
        .first(zc$0$first),
        .nz(zc$0$nz),
        .oz(zc$0$oz),
        .closer(zc$0$closer)
    );
    se$zc$1 zc$1(
        .clock(zc$1$clock),
        .first(zc$1$first),
        .nz(zc$1$nz),
        .oz(zc$1$oz),
        .closer(zc$1$closer)
    );
    se$zc$2 zc$2(
        .clock(zc$2$clock),
        .first(zc$2$first),
        .nz(zc$2$nz),
        .oz(zc$2$oz),
        .closer(zc$2$closer)
    );
    se$zc$3 zc$3(
        .clock(zc$3$clock),
        .first(zc$3$first),
        .nz(zc$3$nz),
        .oz(zc$3$oz),
        .closer(zc$3$closer)
    );
    se$zc$4 zc$4(
        .clock(zc$4$clock),
        .first(zc$4$first),
        .nz(zc$4$nz),
        .oz(zc$4$oz),
        .closer(zc$4$closer)
    );
    se$zc$5 zc$5(
        .clock(zc$5$clock),
        .first(zc$5$first),
        .nz(zc$5$nz),
        .oz(zc$5$oz),
        .closer(zc$5$closer)
    );
    se$zc$6 zc$6(
        .clock(zc$6$clock),
        .first(zc$6$first),
        .nz(zc$6$nz),
        .oz(zc$6$oz),
        .closer(zc$6$closer)
    );
    se$zc$7 zc$7(
        .clock(zc$7$clock),
        .first(zc$7$first),
        .nz(zc$7$nz),
        .oz(zc$7$oz),
        .closer(zc$7$closer)
    );
    se$zc$8 zc$8(
        .clock(zc$8$clock),
        .first(zc$8$first),
        .nz(zc$8$nz),
        .oz(zc$8$oz),
        .closer(zc$8$closer)
    );
    se$zc$9 zc$9(
        .clock(zc$9$clock),
        .first(zc$9$first),
        .nz(zc$9$nz),
        .oz(zc$9$oz),
        .closer(zc$9$closer)
    );
    se$zc$10 zc$10(
        .clock(zc$10$clock),
        .first(zc$10$first),
        .nz(zc$10$nz),
        .oz(zc$10$oz),
        .closer(zc$10$closer)
    );
    se$zc$11 zc$11(
        .clock(zc$11$clock),
        .first(zc$11$first),
        .nz(zc$11$nz),
        .oz(zc$11$oz),
        .closer(zc$11$closer)
    );
    se$zc$12 zc$12(
        .clock(zc$12$clock),
        .first(zc$12$first),
        .nz(zc$12$nz),
        .oz(zc$12$oz),
        .closer(zc$12$closer)
    );
    se$zc$13 zc$13(
        .clock(zc$13$clock),
        .first(zc$13$first),
        .nz(zc$13$nz),
        .oz(zc$13$oz),
        .closer(zc$13$closer)
    );
    se$zc$14 zc$14(
        .clock(zc$14$clock),
        .first(zc$14$first),
        .nz(zc$14$nz),
        .oz(zc$14$oz),
        .closer(zc$14$closer)
    );
    se$zc$15 zc$15(
        .clock(zc$15$clock),
        .first(zc$15$first),
        .nz(zc$15$nz),
        .oz(zc$15$oz),
        .closer(zc$15$closer)
    );
    se$zc$16 zc$16(
        .clock(zc$16$clock),
        .first(zc$16$first),
        .nz(zc$16$nz),
        .oz(zc$16$oz),
        .closer(zc$16$closer)
    );
    se$zc$17 zc$17(
        .clock(zc$17$clock),
        .first(zc$17$first),
        .nz(zc$17$nz),
        .oz(zc$17$oz),
        .closer(zc$17$closer)
    );
    se$zc$18 zc$18(
        .clock(zc$18$clock),
        .first(zc$18$first),
        .nz(zc$18$nz),
        .oz(zc$18$oz),
        .closer(zc$18$closer)
    );
    se$zc$19 zc$19(
        .clock(zc$19$clock),
        .first(zc$19$first),
        .nz(zc$19$nz),
        .oz(zc$19$oz),
        .closer(zc$19$closer)
    );
    se$zc$20 zc$20(
        .clock(zc$20$clock),
        .first(zc$20$first),
        .nz(zc$20$nz),
        .oz(zc$20$oz),
        .closer(zc$20$closer)
    );
    se$zc$21 zc$21(
        .clock(zc$21$clock),
        .first(zc$21$first),
        .nz(zc$21$nz),
        .oz(zc$21$oz),
        .closer(zc$21$closer)
    );
    se$zc$22 zc$22(
        .clock(zc$22$clock),
        .first(zc$22$first),
        .nz(zc$22$nz),
        .oz(zc$22$oz),
        .closer(zc$22$closer)
    );
    se$zc$23 zc$23(
        .clock(zc$23$clock),
        .first(zc$23$first),
        .nz(zc$23$nz),
        .oz(zc$23$oz),
        .closer(zc$23$closer)
    );
    se$zc$24 zc$24(
        .clock(zc$24$clock),
        .first(zc$24$first),
        .nz(zc$24$nz),
        .oz(zc$24$oz),
        .closer(zc$24$closer)
    );
    se$zc$25 zc$25(
        .clock(zc$25$clock),
        .first(zc$25$first),
        .nz(zc$25$nz),
        .oz(zc$25$oz),
        .closer(zc$25$closer)
    );
    se$zc$26 zc$26(
        .clock(zc$26$clock),
        .first(zc$26$first),
        .nz(zc$26$nz),
        .oz(zc$26$oz),
        .closer(zc$26$closer)
    );
    se$zc$27 zc$27(
        .clock(zc$27$clock),
        .first(zc$27$first),
        .nz(zc$27$nz),
        .oz(zc$27$oz),
        .closer(zc$27$closer)
    );
    se$zc$28 zc$28(
        .clock(zc$28$clock),
        .first(zc$28$first),
        .nz(zc$28$nz),
        .oz(zc$28$oz),
        .closer(zc$28$closer)
    );
    se$zc$29 zc$29(
        .clock(zc$29$clock),
        .first(zc$29$first),
        .nz(zc$29$nz),
        .oz(zc$29$oz),
        .closer(zc$29$closer)
    );
    se$zc$30 zc$30(
        .clock(zc$30$clock),
        .first(zc$30$first),
        .nz(zc$30$nz),
        .oz(zc$30$oz),
        .closer(zc$30$closer)
    );
    se$zc$31 zc$31(
        .clock(zc$31$clock),
        .first(zc$31$first),
        .nz(zc$31$nz),
        .oz(zc$31$oz),
        .closer(zc$31$closer)
    );
    se$zc$32 zc$32(
        .clock(zc$32$clock),
        .first(zc$32$first),
        .nz(zc$32$nz),
        .oz(zc$32$oz),
        .closer(zc$32$closer)
    );
    se$zc$33 zc$33(
        .clock(zc$33$clock),
        .first(zc$33$first),
        .nz(zc$33$nz),
        .oz(zc$33$oz),
        .closer(zc$33$closer)
    );
    se$zc$34 zc$34(
        .clock(zc$34$clock),
        .first(zc$34$first),
        .nz(zc$34$nz),
        .oz(zc$34$oz),
        .closer(zc$34$closer)
    );
    se$zc$35 zc$35(
        .clock(zc$35$clock),
        .first(zc$35$first),
        .nz(zc$35$nz),
        .oz(zc$35$oz),
        .closer(zc$35$closer)
    );
    se$zc$36 zc$36(
        .clock(zc$36$clock),
        .first(zc$36$first),
        .nz(zc$36$nz),
        .oz(zc$36$oz),
        .closer(zc$36$closer)
    );
    se$zc$37 zc$37(
        .clock(zc$37$clock),
        .first(zc$37$first),
        .nz(zc$37$nz),
        .oz(zc$37$oz),
        .closer(zc$37$closer)
    );
    se$zc$38 zc$38(
        .clock(zc$38$clock),
        .first(zc$38$first),
        .nz(zc$38$nz),
        .oz(zc$38$oz),
        .closer(zc$38$closer)
    );
    se$zc$39 zc$39(
        .clock(zc$39$clock),
        .first(zc$39$first),
        .nz(zc$39$nz),
        .oz(zc$39$oz),
        .closer(zc$39$closer)
    );
    se$zc$40 zc$40(
        .clock(zc$40$clock),
        .first(zc$40$first),
        .nz(zc$40$nz),
        .oz(zc$40$oz),
        .closer(zc$40$closer)
    );
    se$zc$41 zc$41(
        .clock(zc$41$clock),
        .first(zc$41$first),
        .nz(zc$41$nz),
        .oz(zc$41$oz),
        .closer(zc$41$closer)
    );
    se$zc$42 zc$42(
        .clock(zc$42$clock),
        .first(zc$42$first),
        .nz(zc$42$nz),
        .oz(zc$42$oz),
        .closer(zc$42$closer)
    );
    se$zc$43 zc$43(
        .clock(zc$43$clock),
        .first(zc$43$first),
        .nz(zc$43$nz),
        .oz(zc$43$oz),
        .closer(zc$43$closer)
    );
    se$zc$44 zc$44(
        .clock(zc$44$clock),
        .first(zc$44$first),
        .nz(zc$44$nz),
        .oz(zc$44$oz),
        .closer(zc$44$closer)
    );
    se$zc$45 zc$45(
        .clock(zc$45$clock),
        .first(zc$45$first),
        .nz(zc$45$nz),
        .oz(zc$45$oz),
        .closer(zc$45$closer)
    );
    se$zc$46 zc$46(
        .clock(zc$46$clock),
        .first(zc$46$first),
        .nz(zc$46$nz),
        .oz(zc$46$oz),
        .closer(zc$46$closer)
    );
    se$zc$47 zc$47(
        .clock(zc$47$clock),
        .first(zc$47$first),
        .nz(zc$47$nz),
        .oz(zc$47$oz),
        .closer(zc$47$closer)
    );
    se$zc$48 zc$48(
        .clock(zc$48$clock),
        .first(zc$48$first),
        .nz(zc$48$nz),
        .oz(zc$48$oz),
        .closer(zc$48$closer)
    );
    se$zc$49 zc$49(
        .clock(zc$49$clock),
        .first(zc$49$first),
        .nz(zc$49$nz),
        .oz(zc$49$oz),
        .closer(zc$49$closer)
    );
    se$zc$50 zc$50(
        .clock(zc$50$clock),
        .first(zc$50$first),
        .nz(zc$50$nz),
        .oz(zc$50$oz),
        .closer(zc$50$closer)
    );
    se$zc$51 zc$51(
        .clock(zc$51$clock),
        .first(zc$51$first),
        .nz(zc$51$nz),
        .oz(zc$51$oz),
        .closer(zc$51$closer)
    );
    se$zc$52 zc$52(
        .clock(zc$52$clock),
        .first(zc$52$first),
        .nz(zc$52$nz),
        .oz(zc$52$oz),
        .closer(zc$52$closer)
    );
    se$zc$53 zc$53(
        .clock(zc$53$clock),
        .first(zc$53$first),
        .nz(zc$53$nz),
        .oz(zc$53$oz),
        .closer(zc$53$closer)
    );
    se$zc$54 zc$54(
        .clock(zc$54$clock),
        .first(zc$54$first),
        .nz(zc$54$nz),
        .oz(zc$54$oz),
        .closer(zc$54$closer)
    );
    se$zc$55 zc$55(
        .clock(zc$55$clock),
        .first(zc$55$first),
        .nz(zc$55$nz),
        .oz(zc$55$oz),
        .closer(zc$55$closer)
    );
    se$zc$56 zc$56(
        .clock(zc$56$clock),
        .first(zc$56$first),
        .nz(zc$56$nz),
        .oz(zc$56$oz),
        .closer(zc$56$closer)
    );
    se$zc$57 zc$57(
        .clock(zc$57$clock),
        .first(zc$57$first),
        .nz(zc$57$nz),
        .oz(zc$57$oz),
        .closer(zc$57$closer)
    );
    se$zc$58 zc$58(
        .clock(zc$58$clock),
        .first(zc$58$first),
        .nz(zc$58$nz),
        .oz(zc$58$oz),
        .closer(zc$58$closer)
    );
    se$zc$59 zc$59(
        .clock(zc$59$clock),
        .first(zc$59$first),
        .nz(zc$59$nz),
        .oz(zc$59$oz),
        .closer(zc$59$closer)
    );
    se$zc$60 zc$60(
        .clock(zc$60$clock),
        .first(zc$60$first),
        .nz(zc$60$nz),
        .oz(zc$60$oz),
        .closer(zc$60$closer)
    );
    se$zc$61 zc$61(
        .clock(zc$61$clock),
        .first(zc$61$first),
        .nz(zc$61$nz),
        .oz(zc$61$oz),
        .closer(zc$61$closer)
    );
    se$zc$62 zc$62(
        .clock(zc$62$clock),
        .first(zc$62$first),
        .nz(zc$62$nz),
        .oz(zc$62$oz),
        .closer(zc$62$closer)
    );
    se$zc$63 zc$63(
        .clock(zc$63$clock),
        .first(zc$63$first),
        .nz(zc$63$nz),
        .oz(zc$63$oz),
        .closer(zc$63$closer)
    );
    se$ozm ozm(
        .clock(ozm$clock),
        .we(ozm$we),
        .group(ozm$group),
        .d0(ozm$d0),
        .d1(ozm$d1),
        .d2(ozm$d2),
        .d3(ozm$d3),
        .plane(ozm$plane),
        .px(ozm$px)
    );
    se$nzm nzm(
        .clock(nzm$clock),
        .we(nzm$we),
        .plane(nzm$plane),
        .px(nzm$px),
        .group(nzm$group),
        .w0(nzm$w0),
        .w1(nzm$w1),
        .w2(nzm$w2),
        .w3(nzm$w3)
    );
    se$rm rm(
        .clock(rm$clock),
        .we(rm$we),
        .plane(rm$plane),
        .px(rm$px),
        .group(rm$group),
        .w0(rm$w0),
        .w1(rm$w1),
        .w2(rm$w2),
        .w3(rm$w3)
    );
    se$gm gm(
        .clock(gm$clock),
        .we(gm$we),
        .plane(gm$plane),
        .px(gm$px),
        .group(gm$group),
        .w0(gm$w0),
        .w1(gm$w1),
        .w2(gm$w2),
        .w3(gm$w3)
    );
    se$bm bm(
        .clock(bm$clock),
        .we(bm$we),
        .plane(bm$plane),
        .px(bm$px),
        .group(bm$group),
        .w0(bm$w0),
        .w1(bm$w1),
        .w2(bm$w2),
        .w3(bm$w3)
    );
    se$wes$0 wes$0(
        .d(wes$0$d),
        .q(wes$0$q),
        .clock(wes$0$clock)
    );
    se$wes$1 wes$1(
        .d(wes$1$d),
        .q(wes$1$q),
        .clock(wes$1$clock)
    );
    se$wes$2 wes$2(
        .d(wes$2$d),
        .q(wes$2$q),
        .clock(wes$2$clock)
    );
    se$wes$3 wes$3(
        .d(wes$3$d),
        .q(wes$3$q),
        .clock(wes$3$clock)
    );
    se$wes$4 wes$4(
        .d(wes$4$d),
        .q(wes$4$q),
        .clock(wes$4$clock)
    );
    se$wes$5 wes$5(
        .d(wes$5$d),
        .q(wes$5$q),
        .clock(wes$5$clock)
    );
    se$wes$6 wes$6(
        .d(wes$6$d),
        .q(wes$6$q),
        .clock(wes$6$clock)
    );
    se$wes$7 wes$7(
        .d(wes$7$d),
        .q(wes$7$q),
        .clock(wes$7$clock)
    );
    se$wes$8 wes$8(
        .d(wes$8$d),
        .q(wes$8$q),
        .clock(wes$8$clock)
    );
    se$wes$9 wes$9(
        .d(wes$9$d),
        .q(wes$9$q),
        .clock(wes$9$clock)
    );
    se$wes$10 wes$10(
        .d(wes$10$d),
        .q(wes$10$q),
        .clock(wes$10$clock)
    );
    se$wes$11 wes$11(
        .d(wes$11$d),
        .q(wes$11$q),
        .clock(wes$11$clock)
    );
    se$wes$12 wes$12(
        .d(wes$12$d),
        .q(wes$12$q),
        .clock(wes$12$clock)
    );
    se$wes$13 wes$13(
        .d(wes$13$d),
        .q(wes$13$q),
        .clock(wes$13$clock)
    );
    se$wes$14 wes$14(
        .d(wes$14$d),
        .q(wes$14$q),
        .clock(wes$14$clock)
    );
    se$wes$15 wes$15(
        .d(wes$15$d),
        .q(wes$15$q),
        .clock(wes$15$clock)
    );
    se$wes$16 wes$16(
        .d(wes$16$d),
        .q(wes$16$q),
        .clock(wes$16$clock)
    );
    se$wes$17 wes$17(
        .d(wes$17$d),
        .q(wes$17$q),
        .clock(wes$17$clock)
    );
    se$wes$18 wes$18(
        .d(wes$18$d),
        .q(wes$18$q),
        .clock(wes$18$clock)
    );
    se$wes$19 wes$19(
        .d(wes$19$d),
        .q(wes$19$q),
        .clock(wes$19$clock)
    );
    se$wes$20 wes$20(
        .d(wes$20$d),
        .q(wes$20$q),
        .clock(wes$20$clock)
    );
    se$wes$21 wes$21(
        .d(wes$21$d),
        .q(wes$21$q),
        .clock(wes$21$clock)
    );
    se$wes$22 wes$22(
        .d(wes$22$d),
        .q(wes$22$q),
        .clock(wes$22$clock)
    );
    se$wes$23 wes$23(
        .d(wes$23$d),
        .q(wes$23$q),
        .clock(wes$23$clock)
    );
    se$wes$24 wes$24(
        .d(wes$24$d),
        .q(wes$24$q),
        .clock(wes$24$clock)
    );
    se$wes$25 wes$25(
        .d(wes$25$d),
        .q(wes$25$q),
        .clock(wes$25$clock)
    );
    se$wes$26 wes$26(
        .d(wes$26$d),
        .q(wes$26$q),
        .clock(wes$26$clock)
    );
    se$wes$27 wes$27(
        .d(wes$27$d),
        .q(wes$27$q),
        .clock(wes$27$clock)
    );
    se$wes$28 wes$28(
        .d(wes$28$d),
        .q(wes$28$q),
        .clock(wes$28$clock)
    );
    se$wes$29 wes$29(
        .d(wes$29$d),
        .q(wes$29$q),
        .clock(wes$29$clock)
    );
    se$wes$30 wes$30(
        .d(wes$30$d),
        .q(wes$30$q),
        .clock(wes$30$clock)
    );
    se$wes$31 wes$31(
        .d(wes$31$d),
        .q(wes$31$q),
        .clock(wes$31$clock)
    );
    se$wes$32 wes$32(
        .d(wes$32$d),
        .q(wes$32$q),
        .clock(wes$32$clock)
    );
    se$wes$33 wes$33(
        .d(wes$33$d),
        .q(wes$33$q),
        .clock(wes$33$clock)
    );
    se$wes$34 wes$34(
        .d(wes$34$d),
        .q(wes$34$q),
        .clock(wes$34$clock)
    );
    se$wes$35 wes$35(
        .d(wes$35$d),
        .q(wes$35$q),
        .clock(wes$35$clock)
    );
    se$wes$36 wes$36(
        .d(wes$36$d),
        .q(wes$36$q),
        .clock(wes$36$clock)
    );
    se$wes$37 wes$37(
        .d(wes$37$d),
        .q(wes$37$q),
        .clock(wes$37$clock)
    );
    se$wes$38 wes$38(
        .d(wes$38$d),
        .q(wes$38$q),
        .clock(wes$38$clock)
    );
    se$wes$39 wes$39(
        .d(wes$39$d),
        .q(wes$39$q),
        .clock(wes$39$clock)
    );
    se$wes$40 wes$40(
        .d(wes$40$d),
        .q(wes$40$q),
        .clock(wes$40$clock)
    );
    se$wes$41 wes$41(
        .d(wes$41$d),
        .q(wes$41$q),
        .clock(wes$41$clock)
    );
    se$wes$42 wes$42(
        .d(wes$42$d),
        .q(wes$42$q),
        .clock(wes$42$clock)
    );
    se$wes$43 wes$43(
        .d(wes$43$d),
        .q(wes$43$q),
        .clock(wes$43$clock)
    );
    se$wes$44 wes$44(
        .d(wes$44$d),
        .q(wes$44$q),
        .clock(wes$44$clock)
    );
    se$wes$45 wes$45(
        .d(wes$45$d),
        .q(wes$45$q),
        .clock(wes$45$clock)
    );
    se$wes$46 wes$46(
        .d(wes$46$d),
        .q(wes$46$q),
        .clock(wes$46$clock)
    );
    se$wes$47 wes$47(
        .d(wes$47$d),
        .q(wes$47$q),
        .clock(wes$47$clock)
    );
    se$wes$48 wes$48(
        .d(wes$48$d),
        .q(wes$48$q),
        .clock(wes$48$clock)
    );
    se$wes$49 wes$49(
        .d(wes$49$d),
        .q(wes$49$q),
        .clock(wes$49$clock)
    );
    se$wes$50 wes$50(
        .d(wes$50$d),
        .q(wes$50$q),
        .clock(wes$50$clock)
    );
    se$wes$51 wes$51(
        .d(wes$51$d),
        .q(wes$51$q),
        .clock(wes$51$clock)
    );
    se$wes$52 wes$52(
        .d(wes$52$d),
        .q(wes$52$q),
        .clock(wes$52$clock)
    );
    se$wes$53 wes$53(
        .d(wes$53$d),
        .q(wes$53$q),
        .clock(wes$53$clock)
    );
    se$wes$54 wes$54(
        .d(wes$54$d),
        .q(wes$54$q),
        .clock(wes$54$clock)
    );
    se$wes$55 wes$55(
        .d(wes$55$d),
        .q(wes$55$q),
        .clock(wes$55$clock)
    );
    se$wes$56 wes$56(
        .d(wes$56$d),
        .q(wes$56$q),
        .clock(wes$56$clock)
    );
    se$wes$57 wes$57(
        .d(wes$57$d),
        .q(wes$57$q),
        .clock(wes$57$clock)
    );
    se$wes$58 wes$58(
        .d(wes$58$d),
        .q(wes$58$q),
        .clock(wes$58$clock)
    );
    se$wes$59 wes$59(
        .d(wes$59$d),
        .q(wes$59$q),
        .clock(wes$59$clock)
    );
    se$wes$60 wes$60(
        .d(wes$60$d),
        .q(wes$60$q),
        .clock(wes$60$clock)
    );
    se$wes$61 wes$61(
        .d(wes$61$d),
        .q(wes$61$q),
        .clock(wes$61$clock)
    );
    se$wes$62 wes$62(
        .d(wes$62$d),
        .q(wes$62$q),
        .clock(wes$62$clock)
    );
    se$wes$63 wes$63(
        .d(wes$63$d),
        .q(wes$63$q),
        .clock(wes$63$clock)
    );
    
    // Update code
    always @(*) begin
        h$clock = clock;
        sc$clock = clock;
        att$clock = clock;
        dc$clock = clock;
        dgo$clock = clock;
        ml$clock = clock;
        mr$clock = clock;
        hit$clock = clock;
        ach_z$clock = clock;
        bch_z$clock = clock;
        ach_r$clock = clock;
        bch_r$clock = clock;
        ach_g$clock = clock;
        bch_g$clock = clock;
        ach_b$clock = clock;
        bch_b$clock = clock;
        h$d = h$q;
        sc$d = sc$q;
        att$d = att$q;
        dc$d = dc$q;
        dgo$d = dgo$q;
        ml$d = ml$q;
        mr$d = mr$q;
        hit$d = hit$q;
        ach_z$d = ach_z$q;
        bch_z$d = bch_z$q;
        ach_r$d = ach_r$q;
        bch_r$d = bch_r$q;
        ach_g$d = ach_g$q;
        bch_g$d = bch_g$q;
        ach_b$d = ach_b$q;
        bch_b$d = bch_b$q;
        mul_l$clock = clock;
        mul_r$clock = clock;
        interp$clock = clock;
        ozm$clock = clock;
        nzm$clock = clock;
        rm$clock = clock;
        gm$clock = clock;
        bm$clock = clock;
        zc$0$clock = clock;
        wes$0$clock = clock;
        wes$0$d = wes$0$q;
        zc$1$clock = clock;
        wes$1$clock = clock;
        wes$1$d = wes$1$q;
        zc$2$clock = clock;
        wes$2$clock = clock;
        wes$2$d = wes$2$q;
        zc$3$clock = clock;
        wes$3$clock = clock;
        wes$3$d = wes$3$q;
        zc$4$clock = clock;
        wes$4$clock = clock;
        wes$4$d = wes$4$q;
        zc$5$clock = clock;
        wes$5$clock = clock;
        wes$5$d = wes$5$q;
        zc$6$clock = clock;
        wes$6$clock = clock;
        wes$6$d = wes$6$q;
        zc$7$clock = clock;
        wes$7$clock = clock;
        wes$7$d = wes$7$q;
        zc$8$clock = clock;
        wes$8$clock = clock;
        wes$8$d = wes$8$q;
        zc$9$clock = clock;
        wes$9$clock = clock;
        wes$9$d = wes$9$q;
        zc$10$clock = clock;
        wes$10$clock = clock;
        wes$10$d = wes$10$q;
        zc$11$clock = clock;
        wes$11$clock = clock;
        wes$11$d = wes$11$q;
        zc$12$clock = clock;
        wes$12$clock = clock;
        wes$12$d = wes$12$q;
        zc$13$clock = clock;
        wes$13$clock = clock;
        wes$13$d = wes$13$q;
        zc$14$clock = clock;
        wes$14$clock = clock;
        wes$14$d = wes$14$q;
        zc$15$clock = clock;
        wes$15$clock = clock;
        wes$15$d = wes$15$q;
        zc$16$clock = clock;
        wes$16$clock = clock;
        wes$16$d = wes$16$q;
        zc$17$clock = clock;
        wes$17$clock = clock;
        wes$17$d = wes$17$q;
        zc$18$clock = clock;
        wes$18$clock = clock;
        wes$18$d = wes$18$q;
        zc$19$clock = clock;
        wes$19$clock = clock;
        wes$19$d = wes$19$q;
        zc$20$clock = clock;
        wes$20$clock = clock;
        wes$20$d = wes$20$q;
        zc$21$clock = clock;
        wes$21$clock = clock;
        wes$21$d = wes$21$q;
        zc$22$clock = clock;
        wes$22$clock = clock;
        wes$22$d = wes$22$q;
        zc$23$clock = clock;
        wes$23$clock = clock;
        wes$23$d = wes$23$q;
        zc$24$clock = clock;
        wes$24$clock = clock;
        wes$24$d = wes$24$q;
        zc$25$clock = clock;
        wes$25$clock = clock;
        wes$25$d = wes$25$q;
        zc$26$clock = clock;
        wes$26$clock = clock;
        wes$26$d = wes$26$q;
        zc$27$clock = clock;
        wes$27$clock = clock;
        wes$27$d = wes$27$q;
        zc$28$clock = clock;
        wes$28$clock = clock;
        wes$28$d = wes$28$q;
        zc$29$clock = clock;
        wes$29$clock = clock;
        wes$29$d = wes$29$q;
        zc$30$clock = clock;
        wes$30$clock = clock;
        wes$30$d = wes$30$q;
        zc$31$clock = clock;
        wes$31$clock = clock;
        wes$31$d = wes$31$q;
        zc$32$clock = clock;
        wes$32$clock = clock;
        wes$32$d = wes$32$q;
        zc$33$clock = clock;
        wes$33$clock = clock;
        wes$33$d = wes$33$q;
        zc$34$clock = clock;
        wes$34$clock = clock;
        wes$34$d = wes$34$q;
        zc$35$clock = clock;
        wes$35$clock = clock;
        wes$35$d = wes$35$q;
        zc$36$clock = clock;
        wes$36$clock = clock;
        wes$36$d = wes$36$q;
        zc$37$clock = clock;
        wes$37$clock = clock;
        wes$37$d = wes$37$q;
        zc$38$clock = clock;
        wes$38$clock = clock;
        wes$38$d = wes$38$q;
        zc$39$clock = clock;
        wes$39$clock = clock;
        wes$39$d = wes$39$q;
        zc$40$clock = clock;
        wes$40$clock = clock;
        wes$40$d = wes$40$q;
        zc$41$clock = clock;
        wes$41$clock = clock;
        wes$41$d = wes$41$q;
        zc$42$clock = clock;
        wes$42$clock = clock;
        wes$42$d = wes$42$q;
        zc$43$clock = clock;
        wes$43$clock = clock;
        wes$43$d = wes$43$q;
        zc$44$clock = clock;
        wes$44$clock = clock;
        wes$44$d = wes$44$q;
        zc$45$clock = clock;
        wes$45$clock = clock;
        wes$45$d = wes$45$q;
        zc$46$clock = clock;
        wes$46$clock = clock;
        wes$46$d = wes$46$q;
        zc$47$clock = clock;
        wes$47$clock = clock;
        wes$47$d = wes$47$q;
        zc$48$clock = clock;
        wes$48$clock = clock;
        wes$48$d = wes$48$q;
        zc$49$clock = clock;
        wes$49$clock = clock;
        wes$49$d = wes$49$q;
        zc$50$clock = clock;
        wes$50$clock = clock;
        wes$50$d = wes$50$q;
        zc$51$clock = clock;
        wes$51$clock = clock;
        wes$51$d = wes$51$q;
        zc$52$clock = clock;
        wes$52$clock = clock;
        wes$52$d = wes$52$q;
        zc$53$clock = clock;
        wes$53$clock = clock;
        wes$53$d = wes$53$q;
        zc$54$clock = clock;
        wes$54$clock = clock;
        wes$54$d = wes$54$q;
        zc$55$clock = clock;
        wes$55$clock = clock;
        wes$55$d = wes$55$q;
        zc$56$clock = clock;
        wes$56$clock = clock;
        wes$56$d = wes$56$q;
        zc$57$clock = clock;
        wes$57$clock = clock;
        wes$57$d = wes$57$q;
        zc$58$clock = clock;
        wes$58$clock = clock;
        wes$58$d = wes$58$q;
        zc$59$clock = clock;
        wes$59$clock = clock;
        wes$59$d = wes$59$q;
        zc$60$clock = clock;
        wes$60$clock = clock;
        wes$60$d = wes$60$q;
        zc$61$clock = clock;
        wes$61$clock = clock;
        wes$61$d = wes$61$q;
        zc$62$clock = clock;
        wes$62$clock = clock;
        wes$62$d = wes$62$q;
        zc$63$clock = clock;
        wes$63$clock = clock;
        wes$63$d = wes$63$q;
        rdy = (h$q == 32'h0) | (h$q == k_head);
        accept = valid & rdy;
        h$d = h$q + 32'h1;
        if (rdy) begin
            h$d = 32'h0;
        end
        if (accept) begin
            h$d = 32'h1;
        end
        xlb = xl ^ k_sign;
        xrb = xr ^ k_sign;
        ach_z$d = ach_z$q >> 32'h1;
        bch_z$d = bch_z$q >> 32'h1;
        ach_r$d = ach_r$q >> 32'h1;
        bch_r$d = bch_r$q >> 32'h1;
        ach_g$d = ach_g$q >> 32'h1;
        bch_g$d = bch_g$q >> 32'h1;
        ach_b$d = ach_b$q >> 32'h1;
        bch_b$d = bch_b$q >> 32'h1;
        if (ach_r$q[32'h0]) begin
            ach_z$d = (ach_z$q >> 32'h1) | k_zamsb;
        end
        if (bch_r$q[32'h0]) begin
            bch_z$d = (bch_z$q >> 32'h1) | k_zamsb;
        end
        if (ach_g$q[32'h0]) begin
            ach_r$d = (ach_r$q >> 32'h1) | k_camsb;
        end
        if (bch_g$q[32'h0]) begin
            bch_r$d = (bch_r$q >> 32'h1) | k_camsb;
        end
        if (ach_b$q[32'h0]) begin
            ach_g$d = (ach_g$q >> 32'h1) | k_camsb;
        end
        if (bch_b$q[32'h0]) begin
            bch_g$d = (bch_g$q >> 32'h1) | k_camsb;
        end
        if (accept) begin
            ml$d = 32'h0;
            if (xlb >= k_lo) begin
                ml$d = xl[(32'h0)+:(6)];
            end
            mr$d = ((32'h40 - 32'h1) & 6'h3f);
            if (xrb <= k_hi) begin
                mr$d = xr[(32'h0)+:(6)];
            end
            hit$d = (xlb <= xrb) & (xlb <= k_hi) & (xrb >= k_lo);
            ach_z$d = za;
            bch_z$d = zb;
            ach_r$d = ra;
            bch_r$d = rb;
            ach_g$d = ga;
            bch_g$d = gb;
            ach_b$d = ba;
            bch_b$d = bb;
        end
        ready = rdy;
        ozload = (h$q != 32'h0) & (h$q <= k_q);
        oz_rd = ozload;
        oz_addr = h$q[(32'h0)+:(4)] - 32'h1;
        mfirst = (h$q == 32'h1) | (h$q == k_m1) | (h$q == k_m2) | (h$q == k_m3);
        mul_l$x = k_xl;
        mul_r$x = k_xr;
        mul_l$a = ach_z$q[32'h0];
        mul_r$a = ach_z$q[32'h0];
        mul_l$b = bch_z$q[32'h0];
        mul_r$b = bch_z$q[32'h0];
        mul_l$first = mfirst;
        mul_r$first = mfirst;
        start = 1'b0;
        satt = 32'h0;
        if (h$q == k_t0) begin
            start = 1'b1;
        end
        if (h$q == k_t1) begin
            start = 1'b1;
            satt = 32'h1;
        end
        if (h$q == k_t2) begin
            start = 1'b1;
            satt = 32'h2;
        end
        if (h$q == k_t3) begin
            start = 1'b1;
            satt = 32'h3;
        end
        isz = att$q == 32'h0;
        half = sc$q == 32'h1;
        ext = sc$q > k_cext;
        win = (sc$q >= k_win) & (sc$q <= k_clast);
        send = sc$q == k_clast;
        if (isz) begin
            ext = sc$q > k_zext;
            win = (sc$q >= k_win) & (sc$q <= k_zlast);
            send = sc$q == k_we;
        end
        sc$d = sc$q + 32'h1;
        if ((sc$q == 32'h0) | send) begin
            sc$d = 32'h0;
        end
        if (start) begin
            sc$d = 32'h1;
            att$d = satt;
        end
        mul_l$rnd = half;
        mul_r$rnd = half;
        interp$e0 = mul_l$e;
        interp$e1 = mul_r$e;
        interp$half = half;
        interp$ext = ext;
        zwin = win & isz;
        rwin = win & (att$q == 32'h1);
        gwin = win & (att$q == 32'h2);
        bwin = win & (att$q == 32'h3);
        zfirst = sc$q == k_win;
        welatch = isz & (sc$q == k_we);
        dstart = (att$q == 32'h3) & (sc$q == k_clast);
        ept$xl = ml$q;
        ept$xr = mr$q;
        mask = 32'h0;
        if (hit$q) begin
            mask = ept$px;
        end
        wbit = sc$q - k_win;
        ozm$plane = wbit + 32'h1;
        nzm$plane = wbit;
        rm$plane = wbit;
        gm$plane = wbit;
        bm$plane = wbit;
        nzm$px = interp$px;
        rm$px = interp$px;
        gm$px = interp$px;
        bm$px = interp$px;
        nzm$we = zwin;
        rm$we = rwin;
        gm$we = gwin;
        bm$we = bwin;
        zc$0$first = zfirst;
        zc$0$nz = interp$px[0];
        zc$0$oz = ozm$px[0];
        if (welatch) begin
            wes$0$d = mask[0] & zc$0$closer;
        end
        zc$1$first = zfirst;
        zc$1$nz = interp$px[1];
        zc$1$oz = ozm$px[1];
        if (welatch) begin
            wes$1$d = mask[1] & zc$1$closer;
        end
        zc$2$first = zfirst;
        zc$2$nz = interp$px[2];
        zc$2$oz = ozm$px[2];
        if (welatch) begin
            wes$2$d = mask[2] & zc$2$closer;
        end
        zc$3$first = zfirst;
        zc$3$nz = interp$px[3];
        zc$3$oz = ozm$px[3];
        if (welatch) begin
            wes$3$d = mask[3] & zc$3$closer;
        end
        zc$4$first = zfirst;
        zc$4$nz = interp$px[4];
        zc$4$oz = ozm$px[4];
        if (welatch) begin
            wes$4$d = mask[4] & zc$4$closer;
        end
        zc$5$first = zfirst;
        zc$5$nz = interp$px[5];
        zc$5$oz = ozm$px[5];
        if (welatch) begin
            wes$5$d = mask[5] & zc$5$closer;
        end
        zc$6$first = zfirst;
        zc$6$nz = interp$px[6];
        zc$6$oz = ozm$px[6];
        if (welatch) begin
            wes$6$d = mask[6] & zc$6$closer;
        end
        zc$7$first = zfirst;
        zc$7$nz = interp$px[7];
        zc$7$oz = ozm$px[7];
        if (welatch) begin
            wes$7$d = mask[7] & zc$7$closer;
        end
        zc$8$first = zfirst;
        zc$8$nz = interp$px[8];
        zc$8$oz = ozm$px[8];
        if (welatch) begin
            wes$8$d = mask[8] & zc$8$closer;
        end
        zc$9$first = zfirst;
        zc$9$nz = interp$px[9];
        zc$9$oz = ozm$px[9];
        if (welatch) begin
            wes$9$d = mask[9] & zc$9$closer;
        end
        zc$10$first = zfirst;
        zc$10$nz = interp$px[10];
        zc$10$oz = ozm$px[10];
        if (welatch) begin
            wes$10$d = mask[10] & zc$10$closer;
        end
        zc$11$first = zfirst;
        zc$11$nz = interp$px[11];
        zc$11$oz = ozm$px[11];
        if (welatch) begin
            wes$11$d = mask[11] & zc$11$closer;
        end
        zc$12$first = zfirst;
        zc$12$nz = interp$px[12];
        zc$12$oz = ozm$px[12];
        if (welatch) begin
            wes$12$d = mask[12] & zc$12$closer;
        end
        zc$13$first = zfirst;
        zc$13$nz = interp$px[13];
        zc$13$oz = ozm$px[13];
        if (welatch) begin
            wes$13$d = mask[13] & zc$13$closer;
        end
        zc$14$first = zfirst;
        zc$14$nz = interp$px[14];
        zc$14$oz = ozm$px[14];
        if (welatch) begin
            wes$14$d = mask[14] & zc$14$closer;
        end
        zc$15$first = zfirst;
        zc$15$nz = interp$px[15];
        zc$15$oz = ozm$px[15];
        if (welatch) begin
            wes$15$d = mask[15] & zc$15$closer;
        end
        zc$16$first = zfirst;
        zc$16$nz = interp$px[16];
        zc$16$oz = ozm$px[16];
        if (welatch) begin
            wes$16$d = mask[16] & zc$16$closer;
        end
        zc$17$first = zfirst;
        zc$17$nz = interp$px[17];
        zc$17$oz = ozm$px[17];
        if (welatch) begin
            wes$17$d = mask[17] & zc$17$closer;
        end
        zc$18$first = zfirst;
        zc$18$nz = interp$px[18];
        zc$18$oz = ozm$px[18];
        if (welatch) begin
            wes$18$d = mask[18] & zc$18$closer;
        end
        zc$19$first = zfirst;
        zc$19$nz = interp$px[19];
        zc$19$oz = ozm$px[19];
        if (welatch) begin
            wes$19$d = mask[19] & zc$19$closer;
        end
        zc$20$first = zfirst;
        zc$20$nz = interp$px[20];
        zc$20$oz = ozm$px[20];
        if (welatch) begin
            wes$20$d = mask[20] & zc$20$closer;
        end
        zc$21$first = zfirst;
        zc$21$nz = interp$px[21];
        zc$21$oz = ozm$px[21];
        if (welatch) begin
            wes$21$d = mask[21] & zc$21$closer;
        end
        zc$22$first = zfirst;
        zc$22$nz = interp$px[22];
        zc$22$oz = ozm$px[22];
        if (welatch) begin
            wes$22$d = mask[22] & zc$22$closer;
        end
        zc$23$first = zfirst;
        zc$23$nz = interp$px[23];
        zc$23$oz = ozm$px[23];
        if (welatch) begin
            wes$23$d = mask[23] & zc$23$closer;
        end
        zc$24$first = zfirst;
        zc$24$nz = interp$px[24];
        zc$24$oz = ozm$px[24];
        if (welatch) begin
            wes$24$d = mask[24] & zc$24$closer;
        end
        zc$25$first = zfirst;
        zc$25$nz = interp$px[25];
        zc$25$oz = ozm$px[25];
        if (welatch) begin
            wes$25$d = mask[25] & zc$25$closer;
        end
        zc$26$first = zfirst;
        zc$26$nz = interp$px[26];
        zc$26$oz = ozm$px[26];
        if (welatch) begin
            wes$26$d = mask[26] & zc$26$closer;
        end
        zc$27$first = zfirst;
        zc$27$nz = interp$px[27];
        zc$27$oz = ozm$px[27];
        if (welatch) begin
            wes$27$d = mask[27] & zc$27$closer;
        end
        zc$28$first = zfirst;
        zc$28$nz = interp$px[28];
        zc$28$oz = ozm$px[28];
        if (welatch) begin
            wes$28$d = mask[28] & zc$28$closer;
        end
        zc$29$first = zfirst;
        zc$29$nz = interp$px[29];
        zc$29$oz = ozm$px[29];
        if (welatch) begin
            wes$29$d = mask[29] & zc$29$closer;
        end
        zc$30$first = zfirst;
        zc$30$nz = interp$px[30];
        zc$30$oz = ozm$px[30];
        if (welatch) begin
            wes$30$d = mask[30] & zc$30$closer;
        end
        zc$31$first = zfirst;
        zc$31$nz = interp$px[31];
        zc$31$oz = ozm$px[31];
        if (welatch) begin
            wes$31$d = mask[31] & zc$31$closer;
        end
        zc$32$first = zfirst;
        zc$32$nz = interp$px[32];
        zc$32$oz = ozm$px[32];
        if (welatch) begin
            wes$32$d = mask[32] & zc$32$closer;
        end
        zc$33$first = zfirst;
        zc$33$nz = interp$px[33];
        zc$33$oz = ozm$px[33];
        if (welatch) begin
            wes$33$d = mask[33] & zc$33$closer;
        end
        zc$34$first = zfirst;
        zc$34$nz = interp$px[34];
        zc$34$oz = ozm$px[34];
        if (welatch) begin
            wes$34$d = mask[34] & zc$34$closer;
        end
        zc$35$first = zfirst;
        zc$35$nz = interp$px[35];
        zc$35$oz = ozm$px[35];
        if (welatch) begin
            wes$35$d = mask[35] & zc$35$closer;
        end
        zc$36$first = zfirst;
        zc$36$nz = interp$px[36];
        zc$36$oz = ozm$px[36];
        if (welatch) begin
            wes$36$d = mask[36] & zc$36$closer;
        end
        zc$37$first = zfirst;
        zc$37$nz = interp$px[37];
        zc$37$oz = ozm$px[37];
        if (welatch) begin
            wes$37$d = mask[37] & zc$37$closer;
        end
        zc$38$first = zfirst;
        zc$38$nz = interp$px[38];
        zc$38$oz = ozm$px[38];
        if (welatch) begin
            wes$38$d = mask[38] & zc$38$closer;
        end
        zc$39$first = zfirst;
        zc$39$nz = interp$px[39];
        zc$39$oz = ozm$px[39];
        if (welatch) begin
            wes$39$d = mask[39] & zc$39$closer;
        end
        zc$40$first = zfirst;
        zc$40$nz = interp$px[40];
        zc$40$oz = ozm$px[40];
        if (welatch) begin
            wes$40$d = mask[40] & zc$40$closer;
        end
        zc$41$first = zfirst;
        zc$41$nz = interp$px[41];
        zc$41$oz = ozm$px[41];
        if (welatch) begin
            wes$41$d = mask[41] & zc$41$closer;
        end
        zc$42$first = zfirst;
        zc$42$nz = interp$px[42];
        zc$42$oz = ozm$px[42];
        if (welatch) begin
            wes$42$d = mask[42] & zc$42$closer;
        end
        zc$43$first = zfirst;
        zc$43$nz = interp$px[43];
        zc$43$oz = ozm$px[43];
        if (welatch) begin
            wes$43$d = mask[43] & zc$43$closer;
        end
        zc$44$first = zfirst;
        zc$44$nz = interp$px[44];
        zc$44$oz = ozm$px[44];
        if (welatch) begin
            wes$44$d = mask[44] & zc$44$closer;
        end
        zc$45$first = zfirst;
        zc$45$nz = interp$px[45];
        zc$45$oz = ozm$px[45];
        if (welatch) begin
            wes$45$d = mask[45] & zc$45$closer;
        end
        zc$46$first = zfirst;
        zc$46$nz = interp$px[46];
        zc$46$oz = ozm$px[46];
        if (welatch) begin
            wes$46$d = mask[46] & zc$46$closer;
        end
        zc$47$first = zfirst;
        zc$47$nz = interp$px[47];
        zc$47$oz = ozm$px[47];
        if (welatch) begin
            wes$47$d = mask[47] & zc$47$closer;
        end
        zc$48$first = zfirst;
        zc$48$nz = interp$px[48];
        zc$48$oz = ozm$px[48];
        if (welatch) begin
            wes$48$d = mask[48] & zc$48$closer;
        end
        zc$49$first = zfirst;
        zc$49$nz = interp$px[49];
        zc$49$oz = ozm$px[49];
        if (welatch) begin
            wes$49$d = mask[49] & zc$49$closer;
        end
        zc$50$first = zfirst;
        zc$50$nz = interp$px[50];
        zc$50$oz = ozm$px[50];
        if (welatch) begin
            wes$50$d = mask[50] & zc$50$closer;
        end
        zc$51$first = zfirst;
        zc$51$nz = interp$px[51];
        zc$51$oz = ozm$px[51];
        if (welatch) begin
            wes$51$d = mask[51] & zc$51$closer;
        end
        zc$52$first = zfirst;
        zc$52$nz = interp$px[52];
        zc$52$oz = ozm$px[52];
        if (welatch) begin
            wes$52$d = mask[52] & zc$52$closer;
        end
        zc$53$first = zfirst;
        zc$53$nz = interp$px[53];
        zc$53$oz = ozm$px[53];
        if (welatch) begin
            wes$53$d = mask[53] & zc$53$closer;
        end
        zc$54$first = zfirst;
        zc$54$nz = interp$px[54];
        zc$54$oz = ozm$px[54];
        if (welatch) begin
            wes$54$d = mask[54] & zc$54$closer;
        end
        zc$55$first = zfirst;
        zc$55$nz = interp$px[55];
        zc$55$oz = ozm$px[55];
        if (welatch) begin
            wes$55$d = mask[55] & zc$55$closer;
        end
        zc$56$first = zfirst;
        zc$56$nz = interp$px[56];
        zc$56$oz = ozm$px[56];
        if (welatch) begin
            wes$56$d = mask[56] & zc$56$closer;
        end
        zc$57$first = zfirst;
        zc$57$nz = interp$px[57];
        zc$57$oz = ozm$px[57];
        if (welatch) begin
            wes$57$d = mask[57] & zc$57$closer;
        end
        zc$58$first = zfirst;
        zc$58$nz = interp$px[58];
        zc$58$oz = ozm$px[58];
        if (welatch) begin
            wes$58$d = mask[58] & zc$58$closer;
        end
        zc$59$first = zfirst;
        zc$59$nz = interp$px[59];
        zc$59$oz = ozm$px[59];
        if (welatch) begin
            wes$59$d = mask[59] & zc$59$closer;
        end
        zc$60$first = zfirst;
        zc$60$nz = interp$px[60];
        zc$60$oz = ozm$px[60];
        if (welatch) begin
            wes$60$d = mask[60] & zc$60$closer;
        end
        zc$61$first = zfirst;
        zc$61$nz = interp$px[61];
        zc$61$oz = ozm$px[61];
        if (welatch) begin
            wes$61$d = mask[61] & zc$61$closer;
        end
        zc$62$first = zfirst;
        zc$62$nz = interp$px[62];
        zc$62$oz = ozm$px[62];
        if (welatch) begin
            wes$62$d = mask[62] & zc$62$closer;
        end
        zc$63$first = zfirst;
        zc$63$nz = interp$px[63];
        zc$63$oz = ozm$px[63];
        if (welatch) begin
            wes$63$d = mask[63] & zc$63$closer;
        end
        ozm$we = ozload;
        ozm$group = h$q[(32'h0)+:(4)] - 32'h1;
        ozm$d0 = oz0;
        ozm$d1 = oz1;
        ozm$d2 = oz2;
        ozm$d3 = oz3;
        dump = dc$q != 32'h0;
        dc$d = dc$q + 32'h1;
        if ((dc$q == 32'h0) | (dc$q == k_dq)) begin
            dc$d = 32'h0;
        end
        dgo$d = dstart;
        if (dgo$q) begin
            dc$d = 32'h1;
        end
        og = ((dc$q) & 4'hf) - 32'h1;
        nzm$group = og;
        rm$group = og;
        gm$group = og;
        bm$group = og;
        if (dump) begin
            wes$0$d = wes$4$q;
            wes$1$d = wes$5$q;
            wes$2$d = wes$6$q;
            wes$3$d = wes$7$q;
            wes$4$d = wes$8$q;
            wes$5$d = wes$9$q;
            wes$6$d = wes$10$q;
            wes$7$d = wes$11$q;
            wes$8$d = wes$12$q;
            wes$9$d = wes$13$q;
            wes$10$d = wes$14$q;
            wes$11$d = wes$15$q;
            wes$12$d = wes$16$q;
            wes$13$d = wes$17$q;
            wes$14$d = wes$18$q;
            wes$15$d = wes$19$q;
            wes$16$d = wes$20$q;
            wes$17$d = wes$21$q;
            wes$18$d = wes$22$q;
            wes$19$d = wes$23$q;
            wes$20$d = wes$24$q;
            wes$21$d = wes$25$q;
            wes$22$d = wes$26$q;
            wes$23$d = wes$27$q;
            wes$24$d = wes$28$q;
            wes$25$d = wes$29$q;
            wes$26$d = wes$30$q;
            wes$27$d = wes$31$q;
            wes$28$d = wes$32$q;
            wes$29$d = wes$33$q;
            wes$30$d = wes$34$q;
            wes$31$d = wes$35$q;
            wes$32$d = wes$36$q;
            wes$33$d = wes$37$q;
            wes$34$d = wes$38$q;
            wes$35$d = wes$39$q;
            wes$36$d = wes$40$q;
            wes$37$d = wes$41$q;
            wes$38$d = wes$42$q;
            wes$39$d = wes$43$q;
            wes$40$d = wes$44$q;
            wes$41$d = wes$45$q;
            wes$42$d = wes$46$q;
            wes$43$d = wes$47$q;
            wes$44$d = wes$48$q;
            wes$45$d = wes$49$q;
            wes$46$d = wes$50$q;
            wes$47$d = wes$51$q;
            wes$48$d = wes$52$q;
            wes$49$d = wes$53$q;
            wes$50$d = wes$54$q;
            wes$51$d = wes$55$q;
            wes$52$d = wes$56$q;
            wes$53$d = wes$57$q;
            wes$54$d = wes$58$q;
            wes$55$d = wes$59$q;
            wes$56$d = wes$60$q;
            wes$57$d = wes$61$q;
            wes$58$d = wes$62$q;
            wes$59$d = wes$63$q;
            wes$60$d = 1'b0;
            wes$61$d = 1'b0;
            wes$62$d = 1'b0;
            wes$63$d = 1'b0;
        end
        wr = dump;
        wr_addr = dc$q[(32'h0)+:(4)] - 32'h1;
        nz0 = 32'h0;
        nz1 = 32'h0;
        nz2 = 32'h0;
        nz3 = 32'h0;
        r0 = 32'h0;
        r1 = 32'h0;
        r2 = 32'h0;
        r3 = 32'h0;
        g0 = 32'h0;
        g1 = 32'h0;
        g2 = 32'h0;
        g3 = 32'h0;
        b0 = 32'h0;
        b1 = 32'h0;
        b2 = 32'h0;
        b3 = 32'h0;
        we0 = 1'b0;
        we1 = 1'b0;
        we2 = 1'b0;
        we3 = 1'b0;
        if (dump) begin
            nz0 = nzm$w0;
            nz1 = nzm$w1;
            nz2 = nzm$w2;
            nz3 = nzm$w3;
            r0 = rm$w0;
            r1 = rm$w1;
            r2 = rm$w2;
            r3 = rm$w3;
            g0 = gm$w0;
            g1 = gm$w1;
            g2 = gm$w2;
            g3 = gm$w3;
            b0 = bm$w0;
            b1 = bm$w1;
            b2 = bm$w2;
            b3 = bm$w3;
            we0 = wes$0$q;
            we1 = wes$1$q;
            we2 = wes$2$q;
            we3 = wes$3$q;
        end
    end
    
endmodule // se


module se$ach_b(d,q,clock);
    
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
          
endmodule // se$ach_b


module se$ach_g(d,q,clock);
    
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
          
endmodule // se$ach_g


module se$ach_r(d,q,clock);
    
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
          
endmodule // se$ach_r


module se$ach_z(d,q,clock);
    
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
          
endmodule // se$ach_z


module se$att(d,q,clock);
    
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
          
endmodule // se$att


module se$bch_b(d,q,clock);
    
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
          
endmodule // se$bch_b


module se$bch_g(d,q,clock);
    
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
          
endmodule // se$bch_g


module se$bch_r(d,q,clock);
    
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
          
endmodule // se$bch_r


module se$bch_z(d,q,clock);
    
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
          
endmodule // se$bch_z


module se$bm(clock,we,plane,px,group,w0,w1,w2,w3);
    
    // Module arguments
    input wire  clock;
    input wire  we;
    input wire  [7:0] plane;
    input wire  [63:0] px;
    input wire  [3:0] group;
    output reg  [15:0] w0;
    output reg  [15:0] w1;
    output reg  [15:0] w2;
    output reg  [15:0] w3;
    
    // Update code (custom)
    // Corner turn, bit planes in, words out (rtl::se::turn): 16 memories of 16 x 4 bits;
    // memory m, entry j holds bit (m - j) mod 16 of pixels 4j .. 4j+3.
    wire [3:0] g = group[3:0];
    // The offered plane, registered: written into the memories at the next edge.
    reg we_d;
    reg [7:0] plane_d;
    reg [63:0] px_d;
    initial we_d = 1'b0;
    always @(posedge clock) begin
        we_d <= we;
        plane_d <= plane;
        px_d <= px;
    end
    // Bit plane `plane_d`: group j goes to memory (j + plane_d) mod 16, entry j.
    wire [63:0] planes;
    assign planes[63:0] = px_d;
    wire [319:0] wdata_st;
    assign wdata_st[63:0] = planes;
    assign wdata_st[127:64] = plane_d[0] ? {wdata_st[59:0], wdata_st[63:60]} : wdata_st[63:0];
    assign wdata_st[191:128] = plane_d[1] ? {wdata_st[119:64], wdata_st[127:120]} : wdata_st[127:64];
    assign wdata_st[255:192] = plane_d[2] ? {wdata_st[175:128], wdata_st[191:176]} : wdata_st[191:128];
    assign wdata_st[319:256] = plane_d[3] ? {wdata_st[223:192], wdata_st[255:224]} : wdata_st[255:192];
    wire [63:0] wdata = wdata_st[319:256];
    wire [63:0] rd;
    genvar m;
    generate
    for (m = 0; m < 16; m = m + 1) begin : mem_m
        reg [3:0] mem [0:15];
        wire [7:0] j = (m >= plane_d) ? m - plane_d : m + 16 - plane_d;
        always @(posedge clock) if (we_d && j < 16) mem[j[3:0]] <= wdata[4*m+3:4*m];
        assign rd[4*m+3:4*m] = mem[g];
    end
    endgenerate
    wire [319:0] words_st;
    assign words_st[63:0] = rd;
    assign words_st[127:64] = g[0] ? {words_st[3:0], words_st[63:4]} : words_st[63:0];
    assign words_st[191:128] = g[1] ? {words_st[71:64], words_st[127:72]} : words_st[127:64];
    assign words_st[255:192] = g[2] ? {words_st[143:128], words_st[191:144]} : words_st[191:128];
    assign words_st[319:256] = g[3] ? {words_st[223:192], words_st[255:224]} : words_st[255:192];
    wire [63:0] words = words_st[319:256];
    integer b;
    always @(*) begin
        for (b = 0; b < 16; b = b + 1) w0[b] = words[4*b+0];
        for (b = 0; b < 16; b = b + 1) w1[b] = words[4*b+1];
        for (b = 0; b < 16; b = b + 1) w2[b] = words[4*b+2];
        for (b = 0; b < 16; b = b + 1) w3[b] = words[4*b+3];
    end
endmodule // se$bm


module se$dc(d,q,clock);
    
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
          
endmodule // se$dc


module se$dgo(d,q,clock);
    
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
          
endmodule // se$dgo


module se$ept(xl,xr,px);
    
    // Module arguments
    input wire  [5:0] xl;
    input wire  [5:0] xr;
    output reg  [63:0] px;
    
    // Stub signals
    reg  root$li;
    reg  root$ri;
    reg  root$lcs;
    reg  root$rcs;
    reg  [4:0] root$xl;
    reg  [4:0] root$xr;
    wire  [63:0] root$px;
    
    // Sub module instances
    se$ept$root root(
        .li(root$li),
        .ri(root$ri),
        .lcs(root$lcs),
        .rcs(root$rcs),
        .xl(root$xl),
        .xr(root$xr),
        .px(root$px)
    );
    
    // Update code
    always @(*) begin
        root$li = xl[32'h5];
        root$ri = xr[32'h5];
        root$lcs = 1'b0;
        root$rcs = 1'b0;
        root$xl = xl[(32'h0)+:(5)];
        root$xr = xr[(32'h0)+:(5)];
        px = root$px;
    end
    
endmodule // se$ept


module se$ept$root(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  [4:0] xl;
    input wire  [4:0] xr;
    output reg  [63:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    reg  left$0$li;
    reg  left$0$ri;
    reg  left$0$lcs;
    reg  left$0$rcs;
    reg  [3:0] left$0$xl;
    reg  [3:0] left$0$xr;
    wire  [31:0] left$0$px;
    reg  right$0$li;
    reg  right$0$ri;
    reg  right$0$lcs;
    reg  right$0$rcs;
    reg  [3:0] right$0$xl;
    reg  [3:0] right$0$xr;
    wire  [31:0] right$0$px;
    
    // Sub module instances
    se$ept$root$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    se$ept$root$left$0 left$0(
        .li(left$0$li),
        .ri(left$0$ri),
        .lcs(left$0$lcs),
        .rcs(left$0$rcs),
        .xl(left$0$xl),
        .xr(left$0$xr),
        .px(left$0$px)
    );
    se$ept$root$right$0 right$0(
        .li(right$0$li),
        .ri(right$0$ri),
        .lcs(right$0$lcs),
        .rcs(right$0$rcs),
        .xl(right$0$xl),
        .xr(right$0$xr),
        .px(right$0$px)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl[32'h4];
        pe$xr = xr[32'h4];
        left$0$li = pe$llc;
        left$0$ri = pe$rlc;
        left$0$lcs = pe$lcso;
        left$0$rcs = pe$lrcso;
        left$0$xl = xl[(32'h0)+:(4)];
        left$0$xr = xr[(32'h0)+:(4)];
        right$0$li = pe$lrc;
        right$0$ri = pe$rrc;
        right$0$lcs = pe$lrcso;
        right$0$rcs = pe$rcso;
        right$0$xl = xl[(32'h0)+:(4)];
        right$0$xr = xr[(32'h0)+:(4)];
        px = ((left$0$px) & 64'hffffffffffffffff) | (((right$0$px) & 64'hffffffffffffffff) << 32'h20);
    end
    
endmodule // se$ept$root


module se$ept$root$left$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  [3:0] xl;
    input wire  [3:0] xr;
    output reg  [31:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    reg  left$0$li;
    reg  left$0$ri;
    reg  left$0$lcs;
    reg  left$0$rcs;
    reg  [2:0] left$0$xl;
    reg  [2:0] left$0$xr;
    wire  [15:0] left$0$px;
    reg  right$0$li;
    reg  right$0$ri;
    reg  right$0$lcs;
    reg  right$0$rcs;
    reg  [2:0] right$0$xl;
    reg  [2:0] right$0$xr;
    wire  [15:0] right$0$px;
    
    // Sub module instances
    se$ept$root$left$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    se$ept$root$left$0$left$0 left$0(
        .li(left$0$li),
        .ri(left$0$ri),
        .lcs(left$0$lcs),
        .rcs(left$0$rcs),
        .xl(left$0$xl),
        .xr(left$0$xr),
        .px(left$0$px)
    );
    se$ept$root$left$0$right$0 right$0(
        .li(right$0$li),
        .ri(right$0$ri),
        .lcs(right$0$lcs),
        .rcs(right$0$rcs),
        .xl(right$0$xl),
        .xr(right$0$xr),
        .px(right$0$px)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl[32'h3];
        pe$xr = xr[32'h3];
        left$0$li = pe$llc;
        left$0$ri = pe$rlc;
        left$0$lcs = pe$lcso;
        left$0$rcs = pe$lrcso;
        left$0$xl = xl[(32'h0)+:(3)];
        left$0$xr = xr[(32'h0)+:(3)];
        right$0$li = pe$lrc;
        right$0$ri = pe$rrc;
        right$0$lcs = pe$lrcso;
        right$0$rcs = pe$rcso;
        right$0$xl = xl[(32'h0)+:(3)];
        right$0$xr = xr[(32'h0)+:(3)];
        px = ((left$0$px) & 32'hffffffff) | (((right$0$px) & 32'hffffffff) << 32'h10);
    end
    
endmodule // se$ept$root$left$0


module se$ept$root$left$0$left$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  [2:0] xl;
    input wire  [2:0] xr;
    output reg  [15:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    reg  left$0$li;
    reg  left$0$ri;
    reg  left$0$lcs;
    reg  left$0$rcs;
    reg  [1:0] left$0$xl;
    reg  [1:0] left$0$xr;
    wire  [7:0] left$0$px;
    reg  right$0$li;
    reg  right$0$ri;
    reg  right$0$lcs;
    reg  right$0$rcs;
    reg  [1:0] right$0$xl;
    reg  [1:0] right$0$xr;
    wire  [7:0] right$0$px;
    
    // Sub module instances
    se$ept$root$left$0$left$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    se$ept$root$left$0$left$0$left$0 left$0(
        .li(left$0$li),
        .ri(left$0$ri),
        .lcs(left$0$lcs),
        .rcs(left$0$rcs),
        .xl(left$0$xl),
        .xr(left$0$xr),
        .px(left$0$px)
    );
    se$ept$root$left$0$left$0$right$0 right$0(
        .li(right$0$li),
        .ri(right$0$ri),
        .lcs(right$0$lcs),
        .rcs(right$0$rcs),
        .xl(right$0$xl),
        .xr(right$0$xr),
        .px(right$0$px)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl[32'h2];
        pe$xr = xr[32'h2];
        left$0$li = pe$llc;
        left$0$ri = pe$rlc;
        left$0$lcs = pe$lcso;
        left$0$rcs = pe$lrcso;
        left$0$xl = xl[(32'h0)+:(2)];
        left$0$xr = xr[(32'h0)+:(2)];
        right$0$li = pe$lrc;
        right$0$ri = pe$rrc;
        right$0$lcs = pe$lrcso;
        right$0$rcs = pe$rcso;
        right$0$xl = xl[(32'h0)+:(2)];
        right$0$xr = xr[(32'h0)+:(2)];
        px = ((left$0$px) & 16'hffff) | (((right$0$px) & 16'hffff) << 32'h8);
    end
    
endmodule // se$ept$root$left$0$left$0


module se$ept$root$left$0$left$0$left$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  [1:0] xl;
    input wire  [1:0] xr;
    output reg  [7:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    reg  left$0$li;
    reg  left$0$ri;
    reg  left$0$lcs;
    reg  left$0$rcs;
    reg  left$0$xl;
    reg  left$0$xr;
    wire  [3:0] left$0$px;
    reg  right$0$li;
    reg  right$0$ri;
    reg  right$0$lcs;
    reg  right$0$rcs;
    reg  right$0$xl;
    reg  right$0$xr;
    wire  [3:0] right$0$px;
    
    // Sub module instances
    se$ept$root$left$0$left$0$left$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    se$ept$root$left$0$left$0$left$0$left$0 left$0(
        .li(left$0$li),
        .ri(left$0$ri),
        .lcs(left$0$lcs),
        .rcs(left$0$rcs),
        .xl(left$0$xl),
        .xr(left$0$xr),
        .px(left$0$px)
    );
    se$ept$root$left$0$left$0$left$0$right$0 right$0(
        .li(right$0$li),
        .ri(right$0$ri),
        .lcs(right$0$lcs),
        .rcs(right$0$rcs),
        .xl(right$0$xl),
        .xr(right$0$xr),
        .px(right$0$px)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl[32'h1];
        pe$xr = xr[32'h1];
        left$0$li = pe$llc;
        left$0$ri = pe$rlc;
        left$0$lcs = pe$lcso;
        left$0$rcs = pe$lrcso;
        left$0$xl = xl[(32'h0)+:(1)];
        left$0$xr = xr[(32'h0)+:(1)];
        right$0$li = pe$lrc;
        right$0$ri = pe$rrc;
        right$0$lcs = pe$lrcso;
        right$0$rcs = pe$rcso;
        right$0$xl = xl[(32'h0)+:(1)];
        right$0$xr = xr[(32'h0)+:(1)];
        px = ((left$0$px) & 8'hff) | (((right$0$px) & 8'hff) << 32'h4);
    end
    
endmodule // se$ept$root$left$0$left$0$left$0


module se$ept$root$left$0$left$0$left$0$left$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  xl;
    input wire  xr;
    output reg  [3:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    
    // Local signals
    reg  p0;
    reg  p2;
    
    // Sub module instances
    se$ept$root$left$0$left$0$left$0$left$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl;
        pe$xr = xr;
        p0 = ~pe$llc;
        p2 = ~pe$lrc;
        px = ((((((32'h0) & 4'hf) & ~(1 << (32'h0)) | ((p0) << (32'h0))) & ~(1 << (32'h1)) | ((pe$rlc) << (32'h1))) & ~(1 << (32'h2)) | ((p2) << (32'h2))) & ~(1 << (32'h3)) | ((pe$rrc) << (32'h3)));
    end
    
endmodule // se$ept$root$left$0$left$0$left$0$left$0


module se$ept$root$left$0$left$0$left$0$left$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // se$ept$root$left$0$left$0$left$0$left$0$pe


module se$ept$root$left$0$left$0$left$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // se$ept$root$left$0$left$0$left$0$pe


module se$ept$root$left$0$left$0$left$0$right$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  xl;
    input wire  xr;
    output reg  [3:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    
    // Local signals
    reg  p0;
    reg  p2;
    
    // Sub module instances
    se$ept$root$left$0$left$0$left$0$right$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl;
        pe$xr = xr;
        p0 = ~pe$llc;
        p2 = ~pe$lrc;
        px = ((((((32'h0) & 4'hf) & ~(1 << (32'h0)) | ((p0) << (32'h0))) & ~(1 << (32'h1)) | ((pe$rlc) << (32'h1))) & ~(1 << (32'h2)) | ((p2) << (32'h2))) & ~(1 << (32'h3)) | ((pe$rrc) << (32'h3)));
    end
    
endmodule // se$ept$root$left$0$left$0$left$0$right$0


module se$ept$root$left$0$left$0$left$0$right$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // se$ept$root$left$0$left$0$left$0$right$0$pe


module se$ept$root$left$0$left$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // se$ept$root$left$0$left$0$pe


module se$ept$root$left$0$left$0$right$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  [1:0] xl;
    input wire  [1:0] xr;
    output reg  [7:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    reg  left$0$li;
    reg  left$0$ri;
    reg  left$0$lcs;
    reg  left$0$rcs;
    reg  left$0$xl;
    reg  left$0$xr;
    wire  [3:0] left$0$px;
    reg  right$0$li;
    reg  right$0$ri;
    reg  right$0$lcs;
    reg  right$0$rcs;
    reg  right$0$xl;
    reg  right$0$xr;
    wire  [3:0] right$0$px;
    
    // Sub module instances
    se$ept$root$left$0$left$0$right$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    se$ept$root$left$0$left$0$right$0$left$0 left$0(
        .li(left$0$li),
        .ri(left$0$ri),
        .lcs(left$0$lcs),
        .rcs(left$0$rcs),
        .xl(left$0$xl),
        .xr(left$0$xr),
        .px(left$0$px)
    );
    se$ept$root$left$0$left$0$right$0$right$0 right$0(
        .li(right$0$li),
        .ri(right$0$ri),
        .lcs(right$0$lcs),
        .rcs(right$0$rcs),
        .xl(right$0$xl),
        .xr(right$0$xr),
        .px(right$0$px)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl[32'h1];
        pe$xr = xr[32'h1];
        left$0$li = pe$llc;
        left$0$ri = pe$rlc;
        left$0$lcs = pe$lcso;
        left$0$rcs = pe$lrcso;
        left$0$xl = xl[(32'h0)+:(1)];
        left$0$xr = xr[(32'h0)+:(1)];
        right$0$li = pe$lrc;
        right$0$ri = pe$rrc;
        right$0$lcs = pe$lrcso;
        right$0$rcs = pe$rcso;
        right$0$xl = xl[(32'h0)+:(1)];
        right$0$xr = xr[(32'h0)+:(1)];
        px = ((left$0$px) & 8'hff) | (((right$0$px) & 8'hff) << 32'h4);
    end
    
endmodule // se$ept$root$left$0$left$0$right$0


module se$ept$root$left$0$left$0$right$0$left$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  xl;
    input wire  xr;
    output reg  [3:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    
    // Local signals
    reg  p0;
    reg  p2;
    
    // Sub module instances
    se$ept$root$left$0$left$0$right$0$left$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl;
        pe$xr = xr;
        p0 = ~pe$llc;
        p2 = ~pe$lrc;
        px = ((((((32'h0) & 4'hf) & ~(1 << (32'h0)) | ((p0) << (32'h0))) & ~(1 << (32'h1)) | ((pe$rlc) << (32'h1))) & ~(1 << (32'h2)) | ((p2) << (32'h2))) & ~(1 << (32'h3)) | ((pe$rrc) << (32'h3)));
    end
    
endmodule // se$ept$root$left$0$left$0$right$0$left$0


module se$ept$root$left$0$left$0$right$0$left$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // se$ept$root$left$0$left$0$right$0$left$0$pe


module se$ept$root$left$0$left$0$right$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // se$ept$root$left$0$left$0$right$0$pe


module se$ept$root$left$0$left$0$right$0$right$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  xl;
    input wire  xr;
    output reg  [3:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    
    // Local signals
    reg  p0;
    reg  p2;
    
    // Sub module instances
    se$ept$root$left$0$left$0$right$0$right$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl;
        pe$xr = xr;
        p0 = ~pe$llc;
        p2 = ~pe$lrc;
        px = ((((((32'h0) & 4'hf) & ~(1 << (32'h0)) | ((p0) << (32'h0))) & ~(1 << (32'h1)) | ((pe$rlc) << (32'h1))) & ~(1 << (32'h2)) | ((p2) << (32'h2))) & ~(1 << (32'h3)) | ((pe$rrc) << (32'h3)));
    end
    
endmodule // se$ept$root$left$0$left$0$right$0$right$0


module se$ept$root$left$0$left$0$right$0$right$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // se$ept$root$left$0$left$0$right$0$right$0$pe


module se$ept$root$left$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // se$ept$root$left$0$pe


module se$ept$root$left$0$right$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  [2:0] xl;
    input wire  [2:0] xr;
    output reg  [15:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    reg  left$0$li;
    reg  left$0$ri;
    reg  left$0$lcs;
    reg  left$0$rcs;
    reg  [1:0] left$0$xl;
    reg  [1:0] left$0$xr;
    wire  [7:0] left$0$px;
    reg  right$0$li;
    reg  right$0$ri;
    reg  right$0$lcs;
    reg  right$0$rcs;
    reg  [1:0] right$0$xl;
    reg  [1:0] right$0$xr;
    wire  [7:0] right$0$px;
    
    // Sub module instances
    se$ept$root$left$0$right$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    se$ept$root$left$0$right$0$left$0 left$0(
        .li(left$0$li),
        .ri(left$0$ri),
        .lcs(left$0$lcs),
        .rcs(left$0$rcs),
        .xl(left$0$xl),
        .xr(left$0$xr),
        .px(left$0$px)
    );
    se$ept$root$left$0$right$0$right$0 right$0(
        .li(right$0$li),
        .ri(right$0$ri),
        .lcs(right$0$lcs),
        .rcs(right$0$rcs),
        .xl(right$0$xl),
        .xr(right$0$xr),
        .px(right$0$px)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl[32'h2];
        pe$xr = xr[32'h2];
        left$0$li = pe$llc;
        left$0$ri = pe$rlc;
        left$0$lcs = pe$lcso;
        left$0$rcs = pe$lrcso;
        left$0$xl = xl[(32'h0)+:(2)];
        left$0$xr = xr[(32'h0)+:(2)];
        right$0$li = pe$lrc;
        right$0$ri = pe$rrc;
        right$0$lcs = pe$lrcso;
        right$0$rcs = pe$rcso;
        right$0$xl = xl[(32'h0)+:(2)];
        right$0$xr = xr[(32'h0)+:(2)];
        px = ((left$0$px) & 16'hffff) | (((right$0$px) & 16'hffff) << 32'h8);
    end
    
endmodule // se$ept$root$left$0$right$0


module se$ept$root$left$0$right$0$left$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  [1:0] xl;
    input wire  [1:0] xr;
    output reg  [7:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    reg  left$0$li;
    reg  left$0$ri;
    reg  left$0$lcs;
    reg  left$0$rcs;
    reg  left$0$xl;
    reg  left$0$xr;
    wire  [3:0] left$0$px;
    reg  right$0$li;
    reg  right$0$ri;
    reg  right$0$lcs;
    reg  right$0$rcs;
    reg  right$0$xl;
    reg  right$0$xr;
    wire  [3:0] right$0$px;
    
    // Sub module instances
    se$ept$root$left$0$right$0$left$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    se$ept$root$left$0$right$0$left$0$left$0 left$0(
        .li(left$0$li),
        .ri(left$0$ri),
        .lcs(left$0$lcs),
        .rcs(left$0$rcs),
        .xl(left$0$xl),
        .xr(left$0$xr),
        .px(left$0$px)
    );
    se$ept$root$left$0$right$0$left$0$right$0 right$0(
        .li(right$0$li),
        .ri(right$0$ri),
        .lcs(right$0$lcs),
        .rcs(right$0$rcs),
        .xl(right$0$xl),
        .xr(right$0$xr),
        .px(right$0$px)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl[32'h1];
        pe$xr = xr[32'h1];
        left$0$li = pe$llc;
        left$0$ri = pe$rlc;
        left$0$lcs = pe$lcso;
        left$0$rcs = pe$lrcso;
        left$0$xl = xl[(32'h0)+:(1)];
        left$0$xr = xr[(32'h0)+:(1)];
        right$0$li = pe$lrc;
        right$0$ri = pe$rrc;
        right$0$lcs = pe$lrcso;
        right$0$rcs = pe$rcso;
        right$0$xl = xl[(32'h0)+:(1)];
        right$0$xr = xr[(32'h0)+:(1)];
        px = ((left$0$px) & 8'hff) | (((right$0$px) & 8'hff) << 32'h4);
    end
    
endmodule // se$ept$root$left$0$right$0$left$0


module se$ept$root$left$0$right$0$left$0$left$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  xl;
    input wire  xr;
    output reg  [3:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    
    // Local signals
    reg  p0;
    reg  p2;
    
    // Sub module instances
    se$ept$root$left$0$right$0$left$0$left$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl;
        pe$xr = xr;
        p0 = ~pe$llc;
        p2 = ~pe$lrc;
        px = ((((((32'h0) & 4'hf) & ~(1 << (32'h0)) | ((p0) << (32'h0))) & ~(1 << (32'h1)) | ((pe$rlc) << (32'h1))) & ~(1 << (32'h2)) | ((p2) << (32'h2))) & ~(1 << (32'h3)) | ((pe$rrc) << (32'h3)));
    end
    
endmodule // se$ept$root$left$0$right$0$left$0$left$0


module se$ept$root$left$0$right$0$left$0$left$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // se$ept$root$left$0$right$0$left$0$left$0$pe


module se$ept$root$left$0$right$0$left$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // se$ept$root$left$0$right$0$left$0$pe


module se$ept$root$left$0$right$0$left$0$right$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  xl;
    input wire  xr;
    output reg  [3:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    
    // Local signals
    reg  p0;
    reg  p2;
    
    // Sub module instances
    se$ept$root$left$0$right$0$left$0$right$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl;
        pe$xr = xr;
        p0 = ~pe$llc;
        p2 = ~pe$lrc;
        px = ((((((32'h0) & 4'hf) & ~(1 << (32'h0)) | ((p0) << (32'h0))) & ~(1 << (32'h1)) | ((pe$rlc) << (32'h1))) & ~(1 << (32'h2)) | ((p2) << (32'h2))) & ~(1 << (32'h3)) | ((pe$rrc) << (32'h3)));
    end
    
endmodule // se$ept$root$left$0$right$0$left$0$right$0


module se$ept$root$left$0$right$0$left$0$right$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // se$ept$root$left$0$right$0$left$0$right$0$pe


module se$ept$root$left$0$right$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // se$ept$root$left$0$right$0$pe


module se$ept$root$left$0$right$0$right$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  [1:0] xl;
    input wire  [1:0] xr;
    output reg  [7:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    reg  left$0$li;
    reg  left$0$ri;
    reg  left$0$lcs;
    reg  left$0$rcs;
    reg  left$0$xl;
    reg  left$0$xr;
    wire  [3:0] left$0$px;
    reg  right$0$li;
    reg  right$0$ri;
    reg  right$0$lcs;
    reg  right$0$rcs;
    reg  right$0$xl;
    reg  right$0$xr;
    wire  [3:0] right$0$px;
    
    // Sub module instances
    se$ept$root$left$0$right$0$right$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    se$ept$root$left$0$right$0$right$0$left$0 left$0(
        .li(left$0$li),
        .ri(left$0$ri),
        .lcs(left$0$lcs),
        .rcs(left$0$rcs),
        .xl(left$0$xl),
        .xr(left$0$xr),
        .px(left$0$px)
    );
    se$ept$root$left$0$right$0$right$0$right$0 right$0(
        .li(right$0$li),
        .ri(right$0$ri),
        .lcs(right$0$lcs),
        .rcs(right$0$rcs),
        .xl(right$0$xl),
        .xr(right$0$xr),
        .px(right$0$px)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl[32'h1];
        pe$xr = xr[32'h1];
        left$0$li = pe$llc;
        left$0$ri = pe$rlc;
        left$0$lcs = pe$lcso;
        left$0$rcs = pe$lrcso;
        left$0$xl = xl[(32'h0)+:(1)];
        left$0$xr = xr[(32'h0)+:(1)];
        right$0$li = pe$lrc;
        right$0$ri = pe$rrc;
        right$0$lcs = pe$lrcso;
        right$0$rcs = pe$rcso;
        right$0$xl = xl[(32'h0)+:(1)];
        right$0$xr = xr[(32'h0)+:(1)];
        px = ((left$0$px) & 8'hff) | (((right$0$px) & 8'hff) << 32'h4);
    end
    
endmodule // se$ept$root$left$0$right$0$right$0


module se$ept$root$left$0$right$0$right$0$left$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  xl;
    input wire  xr;
    output reg  [3:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    
    // Local signals
    reg  p0;
    reg  p2;
    
    // Sub module instances
    se$ept$root$left$0$right$0$right$0$left$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl;
        pe$xr = xr;
        p0 = ~pe$llc;
        p2 = ~pe$lrc;
        px = ((((((32'h0) & 4'hf) & ~(1 << (32'h0)) | ((p0) << (32'h0))) & ~(1 << (32'h1)) | ((pe$rlc) << (32'h1))) & ~(1 << (32'h2)) | ((p2) << (32'h2))) & ~(1 << (32'h3)) | ((pe$rrc) << (32'h3)));
    end
    
endmodule // se$ept$root$left$0$right$0$right$0$left$0


module se$ept$root$left$0$right$0$right$0$left$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // se$ept$root$left$0$right$0$right$0$left$0$pe


module se$ept$root$left$0$right$0$right$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // se$ept$root$left$0$right$0$right$0$pe


module se$ept$root$left$0$right$0$right$0$right$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  xl;
    input wire  xr;
    output reg  [3:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    
    // Local signals
    reg  p0;
    reg  p2;
    
    // Sub module instances
    se$ept$root$left$0$right$0$right$0$right$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl;
        pe$xr = xr;
        p0 = ~pe$llc;
        p2 = ~pe$lrc;
        px = ((((((32'h0) & 4'hf) & ~(1 << (32'h0)) | ((p0) << (32'h0))) & ~(1 << (32'h1)) | ((pe$rlc) << (32'h1))) & ~(1 << (32'h2)) | ((p2) << (32'h2))) & ~(1 << (32'h3)) | ((pe$rrc) << (32'h3)));
    end
    
endmodule // se$ept$root$left$0$right$0$right$0$right$0


module se$ept$root$left$0$right$0$right$0$right$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // se$ept$root$left$0$right$0$right$0$right$0$pe


module se$ept$root$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // se$ept$root$pe


module se$ept$root$right$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  [3:0] xl;
    input wire  [3:0] xr;
    output reg  [31:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    reg  left$0$li;
    reg  left$0$ri;
    reg  left$0$lcs;
    reg  left$0$rcs;
    reg  [2:0] left$0$xl;
    reg  [2:0] left$0$xr;
    wire  [15:0] left$0$px;
    reg  right$0$li;
    reg  right$0$ri;
    reg  right$0$lcs;
    reg  right$0$rcs;
    reg  [2:0] right$0$xl;
    reg  [2:0] right$0$xr;
    wire  [15:0] right$0$px;
    
    // Sub module instances
    se$ept$root$right$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    se$ept$root$right$0$left$0 left$0(
        .li(left$0$li),
        .ri(left$0$ri),
        .lcs(left$0$lcs),
        .rcs(left$0$rcs),
        .xl(left$0$xl),
        .xr(left$0$xr),
        .px(left$0$px)
    );
    se$ept$root$right$0$right$0 right$0(
        .li(right$0$li),
        .ri(right$0$ri),
        .lcs(right$0$lcs),
        .rcs(right$0$rcs),
        .xl(right$0$xl),
        .xr(right$0$xr),
        .px(right$0$px)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl[32'h3];
        pe$xr = xr[32'h3];
        left$0$li = pe$llc;
        left$0$ri = pe$rlc;
        left$0$lcs = pe$lcso;
        left$0$rcs = pe$lrcso;
        left$0$xl = xl[(32'h0)+:(3)];
        left$0$xr = xr[(32'h0)+:(3)];
        right$0$li = pe$lrc;
        right$0$ri = pe$rrc;
        right$0$lcs = pe$lrcso;
        right$0$rcs = pe$rcso;
        right$0$xl = xl[(32'h0)+:(3)];
        right$0$xr = xr[(32'h0)+:(3)];
        px = ((left$0$px) & 32'hffffffff) | (((right$0$px) & 32'hffffffff) << 32'h10);
    end
    
endmodule // se$ept$root$right$0


module se$ept$root$right$0$left$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  [2:0] xl;
    input wire  [2:0] xr;
    output reg  [15:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    reg  left$0$li;
    reg  left$0$ri;
    reg  left$0$lcs;
    reg  left$0$rcs;
    reg  [1:0] left$0$xl;
    reg  [1:0] left$0$xr;
    wire  [7:0] left$0$px;
    reg  right$0$li;
    reg  right$0$ri;
    reg  right$0$lcs;
    reg  right$0$rcs;
    reg  [1:0] right$0$xl;
    reg  [1:0] right$0$xr;
    wire  [7:0] right$0$px;
    
    // Sub module instances
    se$ept$root$right$0$left$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    se$ept$root$right$0$left$0$left$0 left$0(
        .li(left$0$li),
        .ri(left$0$ri),
        .lcs(left$0$lcs),
        .rcs(left$0$rcs),
        .xl(left$0$xl),
        .xr(left$0$xr),
        .px(left$0$px)
    );
    se$ept$root$right$0$left$0$right$0 right$0(
        .li(right$0$li),
        .ri(right$0$ri),
        .lcs(right$0$lcs),
        .rcs(right$0$rcs),
        .xl(right$0$xl),
        .xr(right$0$xr),
        .px(right$0$px)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl[32'h2];
        pe$xr = xr[32'h2];
        left$0$li = pe$llc;
        left$0$ri = pe$rlc;
        left$0$lcs = pe$lcso;
        left$0$rcs = pe$lrcso;
        left$0$xl = xl[(32'h0)+:(2)];
        left$0$xr = xr[(32'h0)+:(2)];
        right$0$li = pe$lrc;
        right$0$ri = pe$rrc;
        right$0$lcs = pe$lrcso;
        right$0$rcs = pe$rcso;
        right$0$xl = xl[(32'h0)+:(2)];
        right$0$xr = xr[(32'h0)+:(2)];
        px = ((left$0$px) & 16'hffff) | (((right$0$px) & 16'hffff) << 32'h8);
    end
    
endmodule // se$ept$root$right$0$left$0


module se$ept$root$right$0$left$0$left$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  [1:0] xl;
    input wire  [1:0] xr;
    output reg  [7:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    reg  left$0$li;
    reg  left$0$ri;
    reg  left$0$lcs;
    reg  left$0$rcs;
    reg  left$0$xl;
    reg  left$0$xr;
    wire  [3:0] left$0$px;
    reg  right$0$li;
    reg  right$0$ri;
    reg  right$0$lcs;
    reg  right$0$rcs;
    reg  right$0$xl;
    reg  right$0$xr;
    wire  [3:0] right$0$px;
    
    // Sub module instances
    se$ept$root$right$0$left$0$left$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    se$ept$root$right$0$left$0$left$0$left$0 left$0(
        .li(left$0$li),
        .ri(left$0$ri),
        .lcs(left$0$lcs),
        .rcs(left$0$rcs),
        .xl(left$0$xl),
        .xr(left$0$xr),
        .px(left$0$px)
    );
    se$ept$root$right$0$left$0$left$0$right$0 right$0(
        .li(right$0$li),
        .ri(right$0$ri),
        .lcs(right$0$lcs),
        .rcs(right$0$rcs),
        .xl(right$0$xl),
        .xr(right$0$xr),
        .px(right$0$px)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl[32'h1];
        pe$xr = xr[32'h1];
        left$0$li = pe$llc;
        left$0$ri = pe$rlc;
        left$0$lcs = pe$lcso;
        left$0$rcs = pe$lrcso;
        left$0$xl = xl[(32'h0)+:(1)];
        left$0$xr = xr[(32'h0)+:(1)];
        right$0$li = pe$lrc;
        right$0$ri = pe$rrc;
        right$0$lcs = pe$lrcso;
        right$0$rcs = pe$rcso;
        right$0$xl = xl[(32'h0)+:(1)];
        right$0$xr = xr[(32'h0)+:(1)];
        px = ((left$0$px) & 8'hff) | (((right$0$px) & 8'hff) << 32'h4);
    end
    
endmodule // se$ept$root$right$0$left$0$left$0


module se$ept$root$right$0$left$0$left$0$left$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  xl;
    input wire  xr;
    output reg  [3:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    
    // Local signals
    reg  p0;
    reg  p2;
    
    // Sub module instances
    se$ept$root$right$0$left$0$left$0$left$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl;
        pe$xr = xr;
        p0 = ~pe$llc;
        p2 = ~pe$lrc;
        px = ((((((32'h0) & 4'hf) & ~(1 << (32'h0)) | ((p0) << (32'h0))) & ~(1 << (32'h1)) | ((pe$rlc) << (32'h1))) & ~(1 << (32'h2)) | ((p2) << (32'h2))) & ~(1 << (32'h3)) | ((pe$rrc) << (32'h3)));
    end
    
endmodule // se$ept$root$right$0$left$0$left$0$left$0


module se$ept$root$right$0$left$0$left$0$left$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // se$ept$root$right$0$left$0$left$0$left$0$pe


module se$ept$root$right$0$left$0$left$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // se$ept$root$right$0$left$0$left$0$pe


module se$ept$root$right$0$left$0$left$0$right$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  xl;
    input wire  xr;
    output reg  [3:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    
    // Local signals
    reg  p0;
    reg  p2;
    
    // Sub module instances
    se$ept$root$right$0$left$0$left$0$right$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl;
        pe$xr = xr;
        p0 = ~pe$llc;
        p2 = ~pe$lrc;
        px = ((((((32'h0) & 4'hf) & ~(1 << (32'h0)) | ((p0) << (32'h0))) & ~(1 << (32'h1)) | ((pe$rlc) << (32'h1))) & ~(1 << (32'h2)) | ((p2) << (32'h2))) & ~(1 << (32'h3)) | ((pe$rrc) << (32'h3)));
    end
    
endmodule // se$ept$root$right$0$left$0$left$0$right$0


module se$ept$root$right$0$left$0$left$0$right$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // se$ept$root$right$0$left$0$left$0$right$0$pe


module se$ept$root$right$0$left$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // se$ept$root$right$0$left$0$pe


module se$ept$root$right$0$left$0$right$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  [1:0] xl;
    input wire  [1:0] xr;
    output reg  [7:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    reg  left$0$li;
    reg  left$0$ri;
    reg  left$0$lcs;
    reg  left$0$rcs;
    reg  left$0$xl;
    reg  left$0$xr;
    wire  [3:0] left$0$px;
    reg  right$0$li;
    reg  right$0$ri;
    reg  right$0$lcs;
    reg  right$0$rcs;
    reg  right$0$xl;
    reg  right$0$xr;
    wire  [3:0] right$0$px;
    
    // Sub module instances
    se$ept$root$right$0$left$0$right$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    se$ept$root$right$0$left$0$right$0$left$0 left$0(
        .li(left$0$li),
        .ri(left$0$ri),
        .lcs(left$0$lcs),
        .rcs(left$0$rcs),
        .xl(left$0$xl),
        .xr(left$0$xr),
        .px(left$0$px)
    );
    se$ept$root$right$0$left$0$right$0$right$0 right$0(
        .li(right$0$li),
        .ri(right$0$ri),
        .lcs(right$0$lcs),
        .rcs(right$0$rcs),
        .xl(right$0$xl),
        .xr(right$0$xr),
        .px(right$0$px)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl[32'h1];
        pe$xr = xr[32'h1];
        left$0$li = pe$llc;
        left$0$ri = pe$rlc;
        left$0$lcs = pe$lcso;
        left$0$rcs = pe$lrcso;
        left$0$xl = xl[(32'h0)+:(1)];
        left$0$xr = xr[(32'h0)+:(1)];
        right$0$li = pe$lrc;
        right$0$ri = pe$rrc;
        right$0$lcs = pe$lrcso;
        right$0$rcs = pe$rcso;
        right$0$xl = xl[(32'h0)+:(1)];
        right$0$xr = xr[(32'h0)+:(1)];
        px = ((left$0$px) & 8'hff) | (((right$0$px) & 8'hff) << 32'h4);
    end
    
endmodule // se$ept$root$right$0$left$0$right$0


module se$ept$root$right$0$left$0$right$0$left$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  xl;
    input wire  xr;
    output reg  [3:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    
    // Local signals
    reg  p0;
    reg  p2;
    
    // Sub module instances
    se$ept$root$right$0$left$0$right$0$left$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl;
        pe$xr = xr;
        p0 = ~pe$llc;
        p2 = ~pe$lrc;
        px = ((((((32'h0) & 4'hf) & ~(1 << (32'h0)) | ((p0) << (32'h0))) & ~(1 << (32'h1)) | ((pe$rlc) << (32'h1))) & ~(1 << (32'h2)) | ((p2) << (32'h2))) & ~(1 << (32'h3)) | ((pe$rrc) << (32'h3)));
    end
    
endmodule // se$ept$root$right$0$left$0$right$0$left$0


module se$ept$root$right$0$left$0$right$0$left$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // se$ept$root$right$0$left$0$right$0$left$0$pe


module se$ept$root$right$0$left$0$right$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // se$ept$root$right$0$left$0$right$0$pe


module se$ept$root$right$0$left$0$right$0$right$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  xl;
    input wire  xr;
    output reg  [3:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    
    // Local signals
    reg  p0;
    reg  p2;
    
    // Sub module instances
    se$ept$root$right$0$left$0$right$0$right$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl;
        pe$xr = xr;
        p0 = ~pe$llc;
        p2 = ~pe$lrc;
        px = ((((((32'h0) & 4'hf) & ~(1 << (32'h0)) | ((p0) << (32'h0))) & ~(1 << (32'h1)) | ((pe$rlc) << (32'h1))) & ~(1 << (32'h2)) | ((p2) << (32'h2))) & ~(1 << (32'h3)) | ((pe$rrc) << (32'h3)));
    end
    
endmodule // se$ept$root$right$0$left$0$right$0$right$0


module se$ept$root$right$0$left$0$right$0$right$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // se$ept$root$right$0$left$0$right$0$right$0$pe


module se$ept$root$right$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // se$ept$root$right$0$pe


module se$ept$root$right$0$right$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  [2:0] xl;
    input wire  [2:0] xr;
    output reg  [15:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    reg  left$0$li;
    reg  left$0$ri;
    reg  left$0$lcs;
    reg  left$0$rcs;
    reg  [1:0] left$0$xl;
    reg  [1:0] left$0$xr;
    wire  [7:0] left$0$px;
    reg  right$0$li;
    reg  right$0$ri;
    reg  right$0$lcs;
    reg  right$0$rcs;
    reg  [1:0] right$0$xl;
    reg  [1:0] right$0$xr;
    wire  [7:0] right$0$px;
    
    // Sub module instances
    se$ept$root$right$0$right$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    se$ept$root$right$0$right$0$left$0 left$0(
        .li(left$0$li),
        .ri(left$0$ri),
        .lcs(left$0$lcs),
        .rcs(left$0$rcs),
        .xl(left$0$xl),
        .xr(left$0$xr),
        .px(left$0$px)
    );
    se$ept$root$right$0$right$0$right$0 right$0(
        .li(right$0$li),
        .ri(right$0$ri),
        .lcs(right$0$lcs),
        .rcs(right$0$rcs),
        .xl(right$0$xl),
        .xr(right$0$xr),
        .px(right$0$px)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl[32'h2];
        pe$xr = xr[32'h2];
        left$0$li = pe$llc;
        left$0$ri = pe$rlc;
        left$0$lcs = pe$lcso;
        left$0$rcs = pe$lrcso;
        left$0$xl = xl[(32'h0)+:(2)];
        left$0$xr = xr[(32'h0)+:(2)];
        right$0$li = pe$lrc;
        right$0$ri = pe$rrc;
        right$0$lcs = pe$lrcso;
        right$0$rcs = pe$rcso;
        right$0$xl = xl[(32'h0)+:(2)];
        right$0$xr = xr[(32'h0)+:(2)];
        px = ((left$0$px) & 16'hffff) | (((right$0$px) & 16'hffff) << 32'h8);
    end
    
endmodule // se$ept$root$right$0$right$0


module se$ept$root$right$0$right$0$left$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  [1:0] xl;
    input wire  [1:0] xr;
    output reg  [7:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    reg  left$0$li;
    reg  left$0$ri;
    reg  left$0$lcs;
    reg  left$0$rcs;
    reg  left$0$xl;
    reg  left$0$xr;
    wire  [3:0] left$0$px;
    reg  right$0$li;
    reg  right$0$ri;
    reg  right$0$lcs;
    reg  right$0$rcs;
    reg  right$0$xl;
    reg  right$0$xr;
    wire  [3:0] right$0$px;
    
    // Sub module instances
    se$ept$root$right$0$right$0$left$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    se$ept$root$right$0$right$0$left$0$left$0 left$0(
        .li(left$0$li),
        .ri(left$0$ri),
        .lcs(left$0$lcs),
        .rcs(left$0$rcs),
        .xl(left$0$xl),
        .xr(left$0$xr),
        .px(left$0$px)
    );
    se$ept$root$right$0$right$0$left$0$right$0 right$0(
        .li(right$0$li),
        .ri(right$0$ri),
        .lcs(right$0$lcs),
        .rcs(right$0$rcs),
        .xl(right$0$xl),
        .xr(right$0$xr),
        .px(right$0$px)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl[32'h1];
        pe$xr = xr[32'h1];
        left$0$li = pe$llc;
        left$0$ri = pe$rlc;
        left$0$lcs = pe$lcso;
        left$0$rcs = pe$lrcso;
        left$0$xl = xl[(32'h0)+:(1)];
        left$0$xr = xr[(32'h0)+:(1)];
        right$0$li = pe$lrc;
        right$0$ri = pe$rrc;
        right$0$lcs = pe$lrcso;
        right$0$rcs = pe$rcso;
        right$0$xl = xl[(32'h0)+:(1)];
        right$0$xr = xr[(32'h0)+:(1)];
        px = ((left$0$px) & 8'hff) | (((right$0$px) & 8'hff) << 32'h4);
    end
    
endmodule // se$ept$root$right$0$right$0$left$0


module se$ept$root$right$0$right$0$left$0$left$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  xl;
    input wire  xr;
    output reg  [3:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    
    // Local signals
    reg  p0;
    reg  p2;
    
    // Sub module instances
    se$ept$root$right$0$right$0$left$0$left$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl;
        pe$xr = xr;
        p0 = ~pe$llc;
        p2 = ~pe$lrc;
        px = ((((((32'h0) & 4'hf) & ~(1 << (32'h0)) | ((p0) << (32'h0))) & ~(1 << (32'h1)) | ((pe$rlc) << (32'h1))) & ~(1 << (32'h2)) | ((p2) << (32'h2))) & ~(1 << (32'h3)) | ((pe$rrc) << (32'h3)));
    end
    
endmodule // se$ept$root$right$0$right$0$left$0$left$0


module se$ept$root$right$0$right$0$left$0$left$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // se$ept$root$right$0$right$0$left$0$left$0$pe


module se$ept$root$right$0$right$0$left$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // se$ept$root$right$0$right$0$left$0$pe


module se$ept$root$right$0$right$0$left$0$right$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  xl;
    input wire  xr;
    output reg  [3:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    
    // Local signals
    reg  p0;
    reg  p2;
    
    // Sub module instances
    se$ept$root$right$0$right$0$left$0$right$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl;
        pe$xr = xr;
        p0 = ~pe$llc;
        p2 = ~pe$lrc;
        px = ((((((32'h0) & 4'hf) & ~(1 << (32'h0)) | ((p0) << (32'h0))) & ~(1 << (32'h1)) | ((pe$rlc) << (32'h1))) & ~(1 << (32'h2)) | ((p2) << (32'h2))) & ~(1 << (32'h3)) | ((pe$rrc) << (32'h3)));
    end
    
endmodule // se$ept$root$right$0$right$0$left$0$right$0


module se$ept$root$right$0$right$0$left$0$right$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // se$ept$root$right$0$right$0$left$0$right$0$pe


module se$ept$root$right$0$right$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // se$ept$root$right$0$right$0$pe


module se$ept$root$right$0$right$0$right$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  [1:0] xl;
    input wire  [1:0] xr;
    output reg  [7:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    reg  left$0$li;
    reg  left$0$ri;
    reg  left$0$lcs;
    reg  left$0$rcs;
    reg  left$0$xl;
    reg  left$0$xr;
    wire  [3:0] left$0$px;
    reg  right$0$li;
    reg  right$0$ri;
    reg  right$0$lcs;
    reg  right$0$rcs;
    reg  right$0$xl;
    reg  right$0$xr;
    wire  [3:0] right$0$px;
    
    // Sub module instances
    se$ept$root$right$0$right$0$right$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    se$ept$root$right$0$right$0$right$0$left$0 left$0(
        .li(left$0$li),
        .ri(left$0$ri),
        .lcs(left$0$lcs),
        .rcs(left$0$rcs),
        .xl(left$0$xl),
        .xr(left$0$xr),
        .px(left$0$px)
    );
    se$ept$root$right$0$right$0$right$0$right$0 right$0(
        .li(right$0$li),
        .ri(right$0$ri),
        .lcs(right$0$lcs),
        .rcs(right$0$rcs),
        .xl(right$0$xl),
        .xr(right$0$xr),
        .px(right$0$px)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl[32'h1];
        pe$xr = xr[32'h1];
        left$0$li = pe$llc;
        left$0$ri = pe$rlc;
        left$0$lcs = pe$lcso;
        left$0$rcs = pe$lrcso;
        left$0$xl = xl[(32'h0)+:(1)];
        left$0$xr = xr[(32'h0)+:(1)];
        right$0$li = pe$lrc;
        right$0$ri = pe$rrc;
        right$0$lcs = pe$lrcso;
        right$0$rcs = pe$rcso;
        right$0$xl = xl[(32'h0)+:(1)];
        right$0$xr = xr[(32'h0)+:(1)];
        px = ((left$0$px) & 8'hff) | (((right$0$px) & 8'hff) << 32'h4);
    end
    
endmodule // se$ept$root$right$0$right$0$right$0


module se$ept$root$right$0$right$0$right$0$left$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  xl;
    input wire  xr;
    output reg  [3:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    
    // Local signals
    reg  p0;
    reg  p2;
    
    // Sub module instances
    se$ept$root$right$0$right$0$right$0$left$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl;
        pe$xr = xr;
        p0 = ~pe$llc;
        p2 = ~pe$lrc;
        px = ((((((32'h0) & 4'hf) & ~(1 << (32'h0)) | ((p0) << (32'h0))) & ~(1 << (32'h1)) | ((pe$rlc) << (32'h1))) & ~(1 << (32'h2)) | ((p2) << (32'h2))) & ~(1 << (32'h3)) | ((pe$rrc) << (32'h3)));
    end
    
endmodule // se$ept$root$right$0$right$0$right$0$left$0


module se$ept$root$right$0$right$0$right$0$left$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // se$ept$root$right$0$right$0$right$0$left$0$pe


module se$ept$root$right$0$right$0$right$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // se$ept$root$right$0$right$0$right$0$pe


module se$ept$root$right$0$right$0$right$0$right$0(li,ri,lcs,rcs,xl,xr,px);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  lcs;
    input wire  rcs;
    input wire  xl;
    input wire  xr;
    output reg  [3:0] px;
    
    // Stub signals
    reg  pe$li;
    reg  pe$ri;
    reg  pe$xl;
    reg  pe$xr;
    reg  pe$lcs;
    reg  pe$rcs;
    wire  pe$llc;
    wire  pe$rlc;
    wire  pe$lrc;
    wire  pe$rrc;
    wire  pe$lcso;
    wire  pe$lrcso;
    wire  pe$rcso;
    
    // Local signals
    reg  p0;
    reg  p2;
    
    // Sub module instances
    se$ept$root$right$0$right$0$right$0$right$0$pe pe(
        .li(pe$li),
        .ri(pe$ri),
        .xl(pe$xl),
        .xr(pe$xr),
        .lcs(pe$lcs),
        .rcs(pe$rcs),
        .llc(pe$llc),
        .rlc(pe$rlc),
        .lrc(pe$lrc),
        .rrc(pe$rrc),
        .lcso(pe$lcso),
        .lrcso(pe$lrcso),
        .rcso(pe$rcso)
    );
    
    // Update code
    always @(*) begin
        pe$li = li;
        pe$ri = ri;
        pe$lcs = lcs;
        pe$rcs = rcs;
        pe$xl = xl;
        pe$xr = xr;
        p0 = ~pe$llc;
        p2 = ~pe$lrc;
        px = ((((((32'h0) & 4'hf) & ~(1 << (32'h0)) | ((p0) << (32'h0))) & ~(1 << (32'h1)) | ((pe$rlc) << (32'h1))) & ~(1 << (32'h2)) | ((p2) << (32'h2))) & ~(1 << (32'h3)) | ((pe$rrc) << (32'h3)));
    end
    
endmodule // se$ept$root$right$0$right$0$right$0$right$0


module se$ept$root$right$0$right$0$right$0$right$0$pe(li,ri,xl,xr,lcs,rcs,llc,rlc,lrc,rrc,lcso,lrcso,rcso);
    
    // Module arguments
    input wire  li;
    input wire  ri;
    input wire  xl;
    input wire  xr;
    input wire  lcs;
    input wire  rcs;
    output reg  llc;
    output reg  rlc;
    output reg  lrc;
    output reg  rrc;
    output reg  lcso;
    output reg  lrcso;
    output reg  rcso;
    
    // Local signals
    reg  xl_f;
    reg  xr_f;
    
    // Update code
    always @(*) begin
        xl_f = xl & ~lcs;
        xr_f = xr | rcs;
        lcso = lcs;
        rcso = rcs;
        llc = 1'b1;
        rlc = 1'b0;
        lrc = 1'b1;
        rrc = 1'b0;
        lrcso = 1'b0;
        if (~li & ~ri) begin
            llc = xl_f;
            rlc = xr_f;
        end
        if (li & ri) begin
            lrc = xl_f;
            rrc = xr_f;
        end
        if (~li & ri) begin
            llc = xl_f;
            rlc = 1'b1;
            lrc = 1'b0;
            rrc = xr_f;
            lrcso = 1'b1;
        end
    end
    
endmodule // se$ept$root$right$0$right$0$right$0$right$0$pe


module se$gm(clock,we,plane,px,group,w0,w1,w2,w3);
    
    // Module arguments
    input wire  clock;
    input wire  we;
    input wire  [7:0] plane;
    input wire  [63:0] px;
    input wire  [3:0] group;
    output reg  [15:0] w0;
    output reg  [15:0] w1;
    output reg  [15:0] w2;
    output reg  [15:0] w3;
    
    // Update code (custom)
    // Corner turn, bit planes in, words out (rtl::se::turn): 16 memories of 16 x 4 bits;
    // memory m, entry j holds bit (m - j) mod 16 of pixels 4j .. 4j+3.
    wire [3:0] g = group[3:0];
    // The offered plane, registered: written into the memories at the next edge.
    reg we_d;
    reg [7:0] plane_d;
    reg [63:0] px_d;
    initial we_d = 1'b0;
    always @(posedge clock) begin
        we_d <= we;
        plane_d <= plane;
        px_d <= px;
    end
    // Bit plane `plane_d`: group j goes to memory (j + plane_d) mod 16, entry j.
    wire [63:0] planes;
    assign planes[63:0] = px_d;
    wire [319:0] wdata_st;
    assign wdata_st[63:0] = planes;
    assign wdata_st[127:64] = plane_d[0] ? {wdata_st[59:0], wdata_st[63:60]} : wdata_st[63:0];
    assign wdata_st[191:128] = plane_d[1] ? {wdata_st[119:64], wdata_st[127:120]} : wdata_st[127:64];
    assign wdata_st[255:192] = plane_d[2] ? {wdata_st[175:128], wdata_st[191:176]} : wdata_st[191:128];
    assign wdata_st[319:256] = plane_d[3] ? {wdata_st[223:192], wdata_st[255:224]} : wdata_st[255:192];
    wire [63:0] wdata = wdata_st[319:256];
    wire [63:0] rd;
    genvar m;
    generate
    for (m = 0; m < 16; m = m + 1) begin : mem_m
        reg [3:0] mem [0:15];
        wire [7:0] j = (m >= plane_d) ? m - plane_d : m + 16 - plane_d;
        always @(posedge clock) if (we_d && j < 16) mem[j[3:0]] <= wdata[4*m+3:4*m];
        assign rd[4*m+3:4*m] = mem[g];
    end
    endgenerate
    wire [319:0] words_st;
    assign words_st[63:0] = rd;
    assign words_st[127:64] = g[0] ? {words_st[3:0], words_st[63:4]} : words_st[63:0];
    assign words_st[191:128] = g[1] ? {words_st[71:64], words_st[127:72]} : words_st[127:64];
    assign words_st[255:192] = g[2] ? {words_st[143:128], words_st[191:144]} : words_st[191:128];
    assign words_st[319:256] = g[3] ? {words_st[223:192], words_st[255:224]} : words_st[255:192];
    wire [63:0] words = words_st[319:256];
    integer b;
    always @(*) begin
        for (b = 0; b < 16; b = b + 1) w0[b] = words[4*b+0];
        for (b = 0; b < 16; b = b + 1) w1[b] = words[4*b+1];
        for (b = 0; b < 16; b = b + 1) w2[b] = words[4*b+2];
        for (b = 0; b < 16; b = b + 1) w3[b] = words[4*b+3];
    end
endmodule // se$gm


module se$h(d,q,clock);
    
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
          
endmodule // se$h


module se$hit(d,q,clock);
    
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
          
endmodule // se$hit


module se$interp(clock,e0,e1,half,ext,px);
    
    // Module arguments
    input wire  clock;
    input wire  e0;
    input wire  e1;
    input wire  half;
    input wire  ext;
    output reg  [63:0] px;
    
    // Stub signals
    reg  msb0$d;
    wire  msb0$q;
    reg  msb0$clock;
    reg  msb1$d;
    wire  msb1$q;
    reg  msb1$clock;
    reg  [5:0] e1d$d;
    wire  [5:0] e1d$q;
    reg  e1d$clock;
    reg  [63:0] d$0$d;
    wire  [63:0] d$0$q;
    reg  d$0$clock;
    reg  [63:0] d$1$d;
    wire  [63:0] d$1$q;
    reg  d$1$clock;
    reg  [63:0] d$2$d;
    wire  [63:0] d$2$q;
    reg  d$2$clock;
    reg  [63:0] d$3$d;
    wire  [63:0] d$3$q;
    reg  d$3$clock;
    reg  [63:0] d$4$d;
    wire  [63:0] d$4$q;
    reg  d$4$clock;
    reg  [63:0] d$5$d;
    wire  [63:0] d$5$q;
    reg  d$5$clock;
    reg  lv$0$clock;
    reg  [63:0] lv$0$pts;
    reg  lv$0$e1;
    reg  lv$0$first;
    wire  [63:0] lv$0$n;
    reg  lv$1$clock;
    reg  [63:0] lv$1$pts;
    reg  lv$1$e1;
    reg  lv$1$first;
    wire  [63:0] lv$1$n;
    reg  lv$2$clock;
    reg  [63:0] lv$2$pts;
    reg  lv$2$e1;
    reg  lv$2$first;
    wire  [63:0] lv$2$n;
    reg  lv$3$clock;
    reg  [63:0] lv$3$pts;
    reg  lv$3$e1;
    reg  lv$3$first;
    wire  [63:0] lv$3$n;
    reg  lv$4$clock;
    reg  [63:0] lv$4$pts;
    reg  lv$4$e1;
    reg  lv$4$first;
    wire  [63:0] lv$4$n;
    reg  lv$5$clock;
    reg  [63:0] lv$5$pts;
    reg  lv$5$e1;
    reg  lv$5$first;
    wire  [63:0] lv$5$n;
    
    // Local signals
    reg  in0;
    reg  in1;
    reg  [63:0] a0;
    reg  [63:0] a$0;
    reg  [63:0] a$1;
    reg  [63:0] a$2;
    reg  [63:0] a$3;
    reg  [63:0] a$4;
    reg  [63:0] a$5;
    reg  [63:0] dm$0;
    reg  [63:0] dm$1;
    reg  [63:0] dm$2;
    reg  [63:0] dm$3;
    reg  [63:0] dm$4;
    reg  [63:0] dm$5;
    
    // Sub module instances
    se$interp$msb0 msb0(
        .d(msb0$d),
        .q(msb0$q),
        .clock(msb0$clock)
    );
    se$interp$msb1 msb1(
        .d(msb1$d),
        .q(msb1$q),
        .clock(msb1$clock)
    );
    se$interp$e1d e1d(
        .d(e1d$d),
        .q(e1d$q),
        .clock(e1d$clock)
    );
    se$interp$d$0 d$0(
        .d(d$0$d),
        .q(d$0$q),
        .clock(d$0$clock)
    );
    se$interp$d$1 d$1(
        .d(d$1$d),
        .q(d$1$q),
        .clock(d$1$clock)
    );
    se$interp$d$2 d$2(
        .d(d$2$d),
        .q(d$2$q),
        .clock(d$2$clock)
    );
    se$interp$d$3 d$3(
        .d(d$3$d),
        .q(d$3$q),
        .clock(d$3$clock)
    );
    se$interp$d$4 d$4(
        .d(d$4$d),
        .q(d$4$q),
        .clock(d$4$clock)
    );
    se$interp$d$5 d$5(
        .d(d$5$d),
        .q(d$5$q),
        .clock(d$5$clock)
    );
    se$interp$lv$0 lv$0(
        .clock(lv$0$clock),
        .pts(lv$0$pts),
        .e1(lv$0$e1),
        .first(lv$0$first),
        .n(lv$0$n)
    );
    se$interp$lv$1 lv$1(
        .clock(lv$1$clock),
        .pts(lv$1$pts),
        .e1(lv$1$e1),
        .first(lv$1$first),
        .n(lv$1$n)
    );
    se$interp$lv$2 lv$2(
        .clock(lv$2$clock),
        .pts(lv$2$pts),
        .e1(lv$2$e1),
        .first(lv$2$first),
        .n(lv$2$n)
    );
    se$interp$lv$3 lv$3(
        .clock(lv$3$clock),
        .pts(lv$3$pts),
        .e1(lv$3$e1),
        .first(lv$3$first),
        .n(lv$3$n)
    );
    se$interp$lv$4 lv$4(
        .clock(lv$4$clock),
        .pts(lv$4$pts),
        .e1(lv$4$e1),
        .first(lv$4$first),
        .n(lv$4$n)
    );
    se$interp$lv$5 lv$5(
        .clock(lv$5$clock),
        .pts(lv$5$pts),
        .e1(lv$5$e1),
        .first(lv$5$first),
        .n(lv$5$n)
    );
    
    // Update code
    always @(*) begin
        msb0$clock = clock;
        msb1$clock = clock;
        e1d$clock = clock;
        msb0$d = msb0$q;
        msb1$d = msb1$q;
        e1d$d = e1d$q;
        d$0$clock = clock;
        lv$0$clock = clock;
        lv$0$first = half;
        dm$0 = d$0$q;
        if (half) begin
            dm$0 = 32'h0;
        end
        d$1$clock = clock;
        lv$1$clock = clock;
        lv$1$first = half;
        dm$1 = d$1$q;
        if (half) begin
            dm$1 = 32'h0;
        end
        d$2$clock = clock;
        lv$2$clock = clock;
        lv$2$first = half;
        dm$2 = d$2$q;
        if (half) begin
            dm$2 = 32'h0;
        end
        d$3$clock = clock;
        lv$3$clock = clock;
        lv$3$first = half;
        dm$3 = d$3$q;
        if (half) begin
            dm$3 = 32'h0;
        end
        d$4$clock = clock;
        lv$4$clock = clock;
        lv$4$first = half;
        dm$4 = d$4$q;
        if (half) begin
            dm$4 = 32'h0;
        end
        d$5$clock = clock;
        lv$5$clock = clock;
        lv$5$first = half;
        dm$5 = d$5$q;
        if (half) begin
            dm$5 = 32'h0;
        end
        in0 = e0;
        in1 = e1;
        if (ext) begin
            in0 = msb0$q;
            in1 = msb1$q;
        end
        if (half) begin
            in0 = 1'b1;
            in1 = 1'b1;
        end
        msb0$d = in0;
        msb1$d = in1;
        e1d$d = e1d$q << 32'h1;
        if (in1) begin
            e1d$d = (e1d$q << 32'h1) | 32'h1;
        end
        if (half) begin
            e1d$d = 32'h1;
        end
        a0 = 32'h0;
        if (in0) begin
            a0 = 32'h1;
        end
        lv$0$pts = a0;
        lv$0$e1 = in1;
        d$0$d = a0;
        a$0 = dm$0 | lv$0$n;
        lv$1$pts = a$0;
        lv$1$e1 = e1d$q[1 - 32'h1] & ~half;
        d$1$d = a$0;
        a$1 = dm$1 | lv$1$n;
        lv$2$pts = a$1;
        lv$2$e1 = e1d$q[2 - 32'h1] & ~half;
        d$2$d = a$1;
        a$2 = dm$2 | lv$2$n;
        lv$3$pts = a$2;
        lv$3$e1 = e1d$q[3 - 32'h1] & ~half;
        d$3$d = a$2;
        a$3 = dm$3 | lv$3$n;
        lv$4$pts = a$3;
        lv$4$e1 = e1d$q[4 - 32'h1] & ~half;
        d$4$d = a$3;
        a$4 = dm$4 | lv$4$n;
        lv$5$pts = a$4;
        lv$5$e1 = e1d$q[5 - 32'h1] & ~half;
        d$5$d = a$4;
        a$5 = dm$5 | lv$5$n;
        px = a$5;
    end
    
endmodule // se$interp


module se$interp$d$0(d,q,clock);
    
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
          
endmodule // se$interp$d$0


module se$interp$d$1(d,q,clock);
    
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
          
endmodule // se$interp$d$1


module se$interp$d$2(d,q,clock);
    
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
          
endmodule // se$interp$d$2


module se$interp$d$3(d,q,clock);
    
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
          
endmodule // se$interp$d$3


module se$interp$d$4(d,q,clock);
    
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
          
endmodule // se$interp$d$4


module se$interp$d$5(d,q,clock);
    
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
          
endmodule // se$interp$d$5


module se$interp$e1d(d,q,clock);
    
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
          
endmodule // se$interp$e1d


module se$interp$lv$0(clock,pts,e1,first,n);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] pts;
    input wire  e1;
    input wire  first;
    output reg  [63:0] n;
    
    // Constant declarations
    localparam  lm = 64'h100000000;
    localparam  sh = 16'h20;
    localparam  top = 64'h100000000;
    
    // Stub signals
    reg  [63:0] c$d;
    wire  [63:0] c$q;
    reg  c$clock;
    
    // Local signals
    reg  [63:0] lt;
    reg  [63:0] rt;
    reg  [63:0] cin;
    
    // Sub module instances
    se$interp$lv$0$c c(
        .d(c$d),
        .q(c$q),
        .clock(c$clock)
    );
    
    // Update code
    always @(*) begin
        c$clock = clock;
        c$d = c$q;
        lt = (pts << sh) & lm;
        rt = (pts >> sh) & lm;
        if (e1) begin
            rt = ((pts >> sh) & lm) | top;
        end
        cin = c$q;
        if (first) begin
            cin = 32'h0;
        end
        n = lt ^ rt ^ cin;
        c$d = (lt & rt) | (lt & cin) | (rt & cin);
    end
    
endmodule // se$interp$lv$0


module se$interp$lv$0$c(d,q,clock);
    
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
          
endmodule // se$interp$lv$0$c


module se$interp$lv$1(clock,pts,e1,first,n);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] pts;
    input wire  e1;
    input wire  first;
    output reg  [63:0] n;
    
    // Constant declarations
    localparam  lm = 64'h1000000010000;
    localparam  sh = 16'h10;
    localparam  top = 64'h1000000000000;
    
    // Stub signals
    reg  [63:0] c$d;
    wire  [63:0] c$q;
    reg  c$clock;
    
    // Local signals
    reg  [63:0] lt;
    reg  [63:0] rt;
    reg  [63:0] cin;
    
    // Sub module instances
    se$interp$lv$1$c c(
        .d(c$d),
        .q(c$q),
        .clock(c$clock)
    );
    
    // Update code
    always @(*) begin
        c$clock = clock;
        c$d = c$q;
        lt = (pts << sh) & lm;
        rt = (pts >> sh) & lm;
        if (e1) begin
            rt = ((pts >> sh) & lm) | top;
        end
        cin = c$q;
        if (first) begin
            cin = 32'h0;
        end
        n = lt ^ rt ^ cin;
        c$d = (lt & rt) | (lt & cin) | (rt & cin);
    end
    
endmodule // se$interp$lv$1


module se$interp$lv$1$c(d,q,clock);
    
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
          
endmodule // se$interp$lv$1$c


module se$interp$lv$2(clock,pts,e1,first,n);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] pts;
    input wire  e1;
    input wire  first;
    output reg  [63:0] n;
    
    // Constant declarations
    localparam  lm = 64'h100010001000100;
    localparam  sh = 16'h8;
    localparam  top = 64'h100000000000000;
    
    // Stub signals
    reg  [63:0] c$d;
    wire  [63:0] c$q;
    reg  c$clock;
    
    // Local signals
    reg  [63:0] lt;
    reg  [63:0] rt;
    reg  [63:0] cin;
    
    // Sub module instances
    se$interp$lv$2$c c(
        .d(c$d),
        .q(c$q),
        .clock(c$clock)
    );
    
    // Update code
    always @(*) begin
        c$clock = clock;
        c$d = c$q;
        lt = (pts << sh) & lm;
        rt = (pts >> sh) & lm;
        if (e1) begin
            rt = ((pts >> sh) & lm) | top;
        end
        cin = c$q;
        if (first) begin
            cin = 32'h0;
        end
        n = lt ^ rt ^ cin;
        c$d = (lt & rt) | (lt & cin) | (rt & cin);
    end
    
endmodule // se$interp$lv$2


module se$interp$lv$2$c(d,q,clock);
    
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
          
endmodule // se$interp$lv$2$c


module se$interp$lv$3(clock,pts,e1,first,n);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] pts;
    input wire  e1;
    input wire  first;
    output reg  [63:0] n;
    
    // Constant declarations
    localparam  lm = 64'h1010101010101010;
    localparam  sh = 16'h4;
    localparam  top = 64'h1000000000000000;
    
    // Stub signals
    reg  [63:0] c$d;
    wire  [63:0] c$q;
    reg  c$clock;
    
    // Local signals
    reg  [63:0] lt;
    reg  [63:0] rt;
    reg  [63:0] cin;
    
    // Sub module instances
    se$interp$lv$3$c c(
        .d(c$d),
        .q(c$q),
        .clock(c$clock)
    );
    
    // Update code
    always @(*) begin
        c$clock = clock;
        c$d = c$q;
        lt = (pts << sh) & lm;
        rt = (pts >> sh) & lm;
        if (e1) begin
            rt = ((pts >> sh) & lm) | top;
        end
        cin = c$q;
        if (first) begin
            cin = 32'h0;
        end
        n = lt ^ rt ^ cin;
        c$d = (lt & rt) | (lt & cin) | (rt & cin);
    end
    
endmodule // se$interp$lv$3


module se$interp$lv$3$c(d,q,clock);
    
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
          
endmodule // se$interp$lv$3$c


module se$interp$lv$4(clock,pts,e1,first,n);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] pts;
    input wire  e1;
    input wire  first;
    output reg  [63:0] n;
    
    // Constant declarations
    localparam  lm = 64'h4444444444444444;
    localparam  sh = 16'h2;
    localparam  top = 64'h4000000000000000;
    
    // Stub signals
    reg  [63:0] c$d;
    wire  [63:0] c$q;
    reg  c$clock;
    
    // Local signals
    reg  [63:0] lt;
    reg  [63:0] rt;
    reg  [63:0] cin;
    
    // Sub module instances
    se$interp$lv$4$c c(
        .d(c$d),
        .q(c$q),
        .clock(c$clock)
    );
    
    // Update code
    always @(*) begin
        c$clock = clock;
        c$d = c$q;
        lt = (pts << sh) & lm;
        rt = (pts >> sh) & lm;
        if (e1) begin
            rt = ((pts >> sh) & lm) | top;
        end
        cin = c$q;
        if (first) begin
            cin = 32'h0;
        end
        n = lt ^ rt ^ cin;
        c$d = (lt & rt) | (lt & cin) | (rt & cin);
    end
    
endmodule // se$interp$lv$4


module se$interp$lv$4$c(d,q,clock);
    
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
          
endmodule // se$interp$lv$4$c


module se$interp$lv$5(clock,pts,e1,first,n);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] pts;
    input wire  e1;
    input wire  first;
    output reg  [63:0] n;
    
    // Constant declarations
    localparam  lm = 64'haaaaaaaaaaaaaaaa;
    localparam  sh = 16'h1;
    localparam  top = 64'h8000000000000000;
    
    // Stub signals
    reg  [63:0] c$d;
    wire  [63:0] c$q;
    reg  c$clock;
    
    // Local signals
    reg  [63:0] lt;
    reg  [63:0] rt;
    reg  [63:0] cin;
    
    // Sub module instances
    se$interp$lv$5$c c(
        .d(c$d),
        .q(c$q),
        .clock(c$clock)
    );
    
    // Update code
    always @(*) begin
        c$clock = clock;
        c$d = c$q;
        lt = (pts << sh) & lm;
        rt = (pts >> sh) & lm;
        if (e1) begin
            rt = ((pts >> sh) & lm) | top;
        end
        cin = c$q;
        if (first) begin
            cin = 32'h0;
        end
        n = lt ^ rt ^ cin;
        c$d = (lt & rt) | (lt & cin) | (rt & cin);
    end
    
endmodule // se$interp$lv$5


module se$interp$lv$5$c(d,q,clock);
    
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
          
endmodule // se$interp$lv$5$c


module se$interp$msb0(d,q,clock);
    
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
          
endmodule // se$interp$msb0


module se$interp$msb1(d,q,clock);
    
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
          
endmodule // se$interp$msb1


module se$ml(d,q,clock);
    
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
          
endmodule // se$ml


module se$mr(d,q,clock);
    
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
          
endmodule // se$mr


module se$mul_l(clock,x,a,b,first,rnd,e);
    
    // Module arguments
    input wire  clock;
    input wire  [10:0] x;
    input wire  a;
    input wire  b;
    input wire  first;
    input wire  rnd;
    output reg  e;
    
    // Stub signals
    reg  [10:0] s$d;
    wire  [10:0] s$q;
    reg  s$clock;
    reg  [10:0] c$d;
    wire  [10:0] c$q;
    reg  c$clock;
    reg  cb$d;
    wire  cb$q;
    reg  cb$clock;
    reg  yq$d;
    wire  yq$q;
    reg  yq$clock;
    reg  cr$d;
    wire  cr$q;
    reg  cr$clock;
    
    // Local signals
    reg  [10:0] pp;
    reg  [10:0] sin;
    reg  [10:0] cin;
    reg  [10:0] sum;
    reg  p;
    reg  cbin;
    
    // Sub module instances
    se$mul_l$s s(
        .d(s$d),
        .q(s$q),
        .clock(s$clock)
    );
    se$mul_l$c c(
        .d(c$d),
        .q(c$q),
        .clock(c$clock)
    );
    se$mul_l$cb cb(
        .d(cb$d),
        .q(cb$q),
        .clock(cb$clock)
    );
    se$mul_l$yq yq(
        .d(yq$d),
        .q(yq$q),
        .clock(yq$clock)
    );
    se$mul_l$cr cr(
        .d(cr$d),
        .q(cr$q),
        .clock(cr$clock)
    );
    
    // Update code
    always @(*) begin
        s$clock = clock;
        c$clock = clock;
        cb$clock = clock;
        yq$clock = clock;
        cr$clock = clock;
        s$d = s$q;
        c$d = c$q;
        cb$d = cb$q;
        yq$d = yq$q;
        cr$d = cr$q;
        pp = 32'h0;
        if (a) begin
            pp = x;
        end
        sin = s$q;
        cin = c$q;
        cbin = cb$q;
        if (first) begin
            sin = 32'h0;
            cin = 32'h0;
            cbin = 1'b0;
        end
        sum = pp ^ sin ^ cin;
        c$d = (pp & sin) | (pp & cin) | (sin & cin);
        s$d = sum >> 32'h1;
        p = sum[32'h0];
        yq$d = p ^ b ^ cbin;
        cb$d = (p & b) | (p & cbin) | (b & cbin);
        e = yq$q ^ cr$q;
        cr$d = yq$q & cr$q;
        if (rnd) begin
            cr$d = yq$q;
        end
    end
    
endmodule // se$mul_l


module se$mul_l$c(d,q,clock);
    
    // Module arguments
    input wire  [10:0] d;
    output reg  [10:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 11'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // se$mul_l$c


module se$mul_l$cb(d,q,clock);
    
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
          
endmodule // se$mul_l$cb


module se$mul_l$cr(d,q,clock);
    
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
          
endmodule // se$mul_l$cr


module se$mul_l$s(d,q,clock);
    
    // Module arguments
    input wire  [10:0] d;
    output reg  [10:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 11'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // se$mul_l$s


module se$mul_l$yq(d,q,clock);
    
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
          
endmodule // se$mul_l$yq


module se$mul_r(clock,x,a,b,first,rnd,e);
    
    // Module arguments
    input wire  clock;
    input wire  [10:0] x;
    input wire  a;
    input wire  b;
    input wire  first;
    input wire  rnd;
    output reg  e;
    
    // Stub signals
    reg  [10:0] s$d;
    wire  [10:0] s$q;
    reg  s$clock;
    reg  [10:0] c$d;
    wire  [10:0] c$q;
    reg  c$clock;
    reg  cb$d;
    wire  cb$q;
    reg  cb$clock;
    reg  yq$d;
    wire  yq$q;
    reg  yq$clock;
    reg  cr$d;
    wire  cr$q;
    reg  cr$clock;
    
    // Local signals
    reg  [10:0] pp;
    reg  [10:0] sin;
    reg  [10:0] cin;
    reg  [10:0] sum;
    reg  p;
    reg  cbin;
    
    // Sub module instances
    se$mul_r$s s(
        .d(s$d),
        .q(s$q),
        .clock(s$clock)
    );
    se$mul_r$c c(
        .d(c$d),
        .q(c$q),
        .clock(c$clock)
    );
    se$mul_r$cb cb(
        .d(cb$d),
        .q(cb$q),
        .clock(cb$clock)
    );
    se$mul_r$yq yq(
        .d(yq$d),
        .q(yq$q),
        .clock(yq$clock)
    );
    se$mul_r$cr cr(
        .d(cr$d),
        .q(cr$q),
        .clock(cr$clock)
    );
    
    // Update code
    always @(*) begin
        s$clock = clock;
        c$clock = clock;
        cb$clock = clock;
        yq$clock = clock;
        cr$clock = clock;
        s$d = s$q;
        c$d = c$q;
        cb$d = cb$q;
        yq$d = yq$q;
        cr$d = cr$q;
        pp = 32'h0;
        if (a) begin
            pp = x;
        end
        sin = s$q;
        cin = c$q;
        cbin = cb$q;
        if (first) begin
            sin = 32'h0;
            cin = 32'h0;
            cbin = 1'b0;
        end
        sum = pp ^ sin ^ cin;
        c$d = (pp & sin) | (pp & cin) | (sin & cin);
        s$d = sum >> 32'h1;
        p = sum[32'h0];
        yq$d = p ^ b ^ cbin;
        cb$d = (p & b) | (p & cbin) | (b & cbin);
        e = yq$q ^ cr$q;
        cr$d = yq$q & cr$q;
        if (rnd) begin
            cr$d = yq$q;
        end
    end
    
endmodule // se$mul_r


module se$mul_r$c(d,q,clock);
    
    // Module arguments
    input wire  [10:0] d;
    output reg  [10:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 11'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // se$mul_r$c


module se$mul_r$cb(d,q,clock);
    
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
          
endmodule // se$mul_r$cb


module se$mul_r$cr(d,q,clock);
    
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
          
endmodule // se$mul_r$cr


module se$mul_r$s(d,q,clock);
    
    // Module arguments
    input wire  [10:0] d;
    output reg  [10:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 11'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // se$mul_r$s


module se$mul_r$yq(d,q,clock);
    
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
          
endmodule // se$mul_r$yq


module se$nzm(clock,we,plane,px,group,w0,w1,w2,w3);
    
    // Module arguments
    input wire  clock;
    input wire  we;
    input wire  [7:0] plane;
    input wire  [63:0] px;
    input wire  [3:0] group;
    output reg  [23:0] w0;
    output reg  [23:0] w1;
    output reg  [23:0] w2;
    output reg  [23:0] w3;
    
    // Update code (custom)
    // Corner turn, bit planes in, words out (rtl::se::turn): 24 memories of 16 x 4 bits;
    // memory m, entry j holds bit (m - j) mod 24 of pixels 4j .. 4j+3.
    wire [3:0] g = group[3:0];
    // The offered plane, registered: written into the memories at the next edge.
    reg we_d;
    reg [7:0] plane_d;
    reg [63:0] px_d;
    initial we_d = 1'b0;
    always @(posedge clock) begin
        we_d <= we;
        plane_d <= plane;
        px_d <= px;
    end
    // Bit plane `plane_d`: group j goes to memory (j + plane_d) mod 24, entry j.
    wire [95:0] planes;
    assign planes[63:0] = px_d;
    assign planes[95:64] = 32'd0;
    wire [575:0] wdata_st;
    assign wdata_st[95:0] = planes;
    assign wdata_st[191:96] = plane_d[0] ? {wdata_st[91:0], wdata_st[95:92]} : wdata_st[95:0];
    assign wdata_st[287:192] = plane_d[1] ? {wdata_st[183:96], wdata_st[191:184]} : wdata_st[191:96];
    assign wdata_st[383:288] = plane_d[2] ? {wdata_st[271:192], wdata_st[287:272]} : wdata_st[287:192];
    assign wdata_st[479:384] = plane_d[3] ? {wdata_st[351:288], wdata_st[383:352]} : wdata_st[383:288];
    assign wdata_st[575:480] = plane_d[4] ? {wdata_st[415:384], wdata_st[479:416]} : wdata_st[479:384];
    wire [95:0] wdata = wdata_st[575:480];
    wire [95:0] rd;
    genvar m;
    generate
    for (m = 0; m < 24; m = m + 1) begin : mem_m
        reg [3:0] mem [0:15];
        wire [7:0] j = (m >= plane_d) ? m - plane_d : m + 24 - plane_d;
        always @(posedge clock) if (we_d && j < 16) mem[j[3:0]] <= wdata[4*m+3:4*m];
        assign rd[4*m+3:4*m] = mem[g];
    end
    endgenerate
    wire [479:0] words_st;
    assign words_st[95:0] = rd;
    assign words_st[191:96] = g[0] ? {words_st[3:0], words_st[95:4]} : words_st[95:0];
    assign words_st[287:192] = g[1] ? {words_st[103:96], words_st[191:104]} : words_st[191:96];
    assign words_st[383:288] = g[2] ? {words_st[207:192], words_st[287:208]} : words_st[287:192];
    assign words_st[479:384] = g[3] ? {words_st[319:288], words_st[383:320]} : words_st[383:288];
    wire [95:0] words = words_st[479:384];
    integer b;
    always @(*) begin
        for (b = 0; b < 24; b = b + 1) w0[b] = words[4*b+0];
        for (b = 0; b < 24; b = b + 1) w1[b] = words[4*b+1];
        for (b = 0; b < 24; b = b + 1) w2[b] = words[4*b+2];
        for (b = 0; b < 24; b = b + 1) w3[b] = words[4*b+3];
    end
endmodule // se$nzm


module se$ozm(clock,we,group,d0,d1,d2,d3,plane,px);
    
    // Module arguments
    input wire  clock;
    input wire  we;
    input wire  [3:0] group;
    input wire  [23:0] d0;
    input wire  [23:0] d1;
    input wire  [23:0] d2;
    input wire  [23:0] d3;
    input wire  [7:0] plane;
    output reg  [63:0] px;
    
    // Update code (custom)
    // Corner turn, words in, bit planes out (rtl::se::turn): 24 memories of 16 x 4 bits;
    // memory m, entry j holds bit (m - j) mod 24 of pixels 4j .. 4j+3.
    wire [3:0] g = group[3:0];
    // Group g's words, slot b = bit b of the 4 words, rotated left by g slots.
    reg [95:0] slots;
    integer b;
    always @(*) for (b = 0; b < 24; b = b + 1) slots[4*b+:4] = {d3[b], d2[b], d1[b], d0[b]};
    wire [479:0] wdata_st;
    assign wdata_st[95:0] = slots;
    assign wdata_st[191:96] = g[0] ? {wdata_st[91:0], wdata_st[95:92]} : wdata_st[95:0];
    assign wdata_st[287:192] = g[1] ? {wdata_st[183:96], wdata_st[191:184]} : wdata_st[191:96];
    assign wdata_st[383:288] = g[2] ? {wdata_st[271:192], wdata_st[287:272]} : wdata_st[287:192];
    assign wdata_st[479:384] = g[3] ? {wdata_st[351:288], wdata_st[383:352]} : wdata_st[383:288];
    wire [95:0] wdata = wdata_st[479:384];
    // The plane shown and the memories' read addresses (`ra` in each), registered.
    reg [4:0] shown;
    initial shown = 0;
    always @(posedge clock) shown <= plane[4:0];
    wire [95:0] rd;
    genvar m;
    generate
    for (m = 0; m < 24; m = m + 1) begin : mem_m
        reg [3:0] mem [0:15];
        wire [3:0] j = (m >= plane) ? m - plane : m + 24 - plane;
        always @(posedge clock) if (we) mem[g] <= wdata[4*m+3:4*m];
        reg [3:0] ra;
        initial ra = m;
        always @(posedge clock) ra <= j;
        assign rd[4*m+3:4*m] = mem[ra];
    end
    endgenerate
    wire [575:0] turned_st;
    assign turned_st[95:0] = rd;
    assign turned_st[191:96] = shown[0] ? {turned_st[3:0], turned_st[95:4]} : turned_st[95:0];
    assign turned_st[287:192] = shown[1] ? {turned_st[103:96], turned_st[191:104]} : turned_st[191:96];
    assign turned_st[383:288] = shown[2] ? {turned_st[207:192], turned_st[287:208]} : turned_st[287:192];
    assign turned_st[479:384] = shown[3] ? {turned_st[319:288], turned_st[383:320]} : turned_st[383:288];
    assign turned_st[575:480] = shown[4] ? {turned_st[447:384], turned_st[479:448]} : turned_st[479:384];
    wire [95:0] turned = turned_st[575:480];
    always @(*) px = turned[63:0];
endmodule // se$ozm


module se$rm(clock,we,plane,px,group,w0,w1,w2,w3);
    
    // Module arguments
    input wire  clock;
    input wire  we;
    input wire  [7:0] plane;
    input wire  [63:0] px;
    input wire  [3:0] group;
    output reg  [15:0] w0;
    output reg  [15:0] w1;
    output reg  [15:0] w2;
    output reg  [15:0] w3;
    
    // Update code (custom)
    // Corner turn, bit planes in, words out (rtl::se::turn): 16 memories of 16 x 4 bits;
    // memory m, entry j holds bit (m - j) mod 16 of pixels 4j .. 4j+3.
    wire [3:0] g = group[3:0];
    // The offered plane, registered: written into the memories at the next edge.
    reg we_d;
    reg [7:0] plane_d;
    reg [63:0] px_d;
    initial we_d = 1'b0;
    always @(posedge clock) begin
        we_d <= we;
        plane_d <= plane;
        px_d <= px;
    end
    // Bit plane `plane_d`: group j goes to memory (j + plane_d) mod 16, entry j.
    wire [63:0] planes;
    assign planes[63:0] = px_d;
    wire [319:0] wdata_st;
    assign wdata_st[63:0] = planes;
    assign wdata_st[127:64] = plane_d[0] ? {wdata_st[59:0], wdata_st[63:60]} : wdata_st[63:0];
    assign wdata_st[191:128] = plane_d[1] ? {wdata_st[119:64], wdata_st[127:120]} : wdata_st[127:64];
    assign wdata_st[255:192] = plane_d[2] ? {wdata_st[175:128], wdata_st[191:176]} : wdata_st[191:128];
    assign wdata_st[319:256] = plane_d[3] ? {wdata_st[223:192], wdata_st[255:224]} : wdata_st[255:192];
    wire [63:0] wdata = wdata_st[319:256];
    wire [63:0] rd;
    genvar m;
    generate
    for (m = 0; m < 16; m = m + 1) begin : mem_m
        reg [3:0] mem [0:15];
        wire [7:0] j = (m >= plane_d) ? m - plane_d : m + 16 - plane_d;
        always @(posedge clock) if (we_d && j < 16) mem[j[3:0]] <= wdata[4*m+3:4*m];
        assign rd[4*m+3:4*m] = mem[g];
    end
    endgenerate
    wire [319:0] words_st;
    assign words_st[63:0] = rd;
    assign words_st[127:64] = g[0] ? {words_st[3:0], words_st[63:4]} : words_st[63:0];
    assign words_st[191:128] = g[1] ? {words_st[71:64], words_st[127:72]} : words_st[127:64];
    assign words_st[255:192] = g[2] ? {words_st[143:128], words_st[191:144]} : words_st[191:128];
    assign words_st[319:256] = g[3] ? {words_st[223:192], words_st[255:224]} : words_st[255:192];
    wire [63:0] words = words_st[319:256];
    integer b;
    always @(*) begin
        for (b = 0; b < 16; b = b + 1) w0[b] = words[4*b+0];
        for (b = 0; b < 16; b = b + 1) w1[b] = words[4*b+1];
        for (b = 0; b < 16; b = b + 1) w2[b] = words[4*b+2];
        for (b = 0; b < 16; b = b + 1) w3[b] = words[4*b+3];
    end
endmodule // se$rm


module se$sc(d,q,clock);
    
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
          
endmodule // se$sc


module se$wes$0(d,q,clock);
    
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
          
endmodule // se$wes$0


module se$wes$1(d,q,clock);
    
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
          
endmodule // se$wes$1


module se$wes$10(d,q,clock);
    
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
          
endmodule // se$wes$10


module se$wes$11(d,q,clock);
    
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
          
endmodule // se$wes$11


module se$wes$12(d,q,clock);
    
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
          
endmodule // se$wes$12


module se$wes$13(d,q,clock);
    
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
          
endmodule // se$wes$13


module se$wes$14(d,q,clock);
    
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
          
endmodule // se$wes$14


module se$wes$15(d,q,clock);
    
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
          
endmodule // se$wes$15


module se$wes$16(d,q,clock);
    
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
          
endmodule // se$wes$16


module se$wes$17(d,q,clock);
    
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
          
endmodule // se$wes$17


module se$wes$18(d,q,clock);
    
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
          
endmodule // se$wes$18


module se$wes$19(d,q,clock);
    
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
          
endmodule // se$wes$19


module se$wes$2(d,q,clock);
    
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
          
endmodule // se$wes$2


module se$wes$20(d,q,clock);
    
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
          
endmodule // se$wes$20


module se$wes$21(d,q,clock);
    
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
          
endmodule // se$wes$21


module se$wes$22(d,q,clock);
    
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
          
endmodule // se$wes$22


module se$wes$23(d,q,clock);
    
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
          
endmodule // se$wes$23


module se$wes$24(d,q,clock);
    
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
          
endmodule // se$wes$24


module se$wes$25(d,q,clock);
    
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
          
endmodule // se$wes$25


module se$wes$26(d,q,clock);
    
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
          
endmodule // se$wes$26


module se$wes$27(d,q,clock);
    
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
          
endmodule // se$wes$27


module se$wes$28(d,q,clock);
    
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
          
endmodule // se$wes$28


module se$wes$29(d,q,clock);
    
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
          
endmodule // se$wes$29


module se$wes$3(d,q,clock);
    
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
          
endmodule // se$wes$3


module se$wes$30(d,q,clock);
    
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
          
endmodule // se$wes$30


module se$wes$31(d,q,clock);
    
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
          
endmodule // se$wes$31


module se$wes$32(d,q,clock);
    
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
          
endmodule // se$wes$32


module se$wes$33(d,q,clock);
    
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
          
endmodule // se$wes$33


module se$wes$34(d,q,clock);
    
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
          
endmodule // se$wes$34


module se$wes$35(d,q,clock);
    
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
          
endmodule // se$wes$35


module se$wes$36(d,q,clock);
    
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
          
endmodule // se$wes$36


module se$wes$37(d,q,clock);
    
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
          
endmodule // se$wes$37


module se$wes$38(d,q,clock);
    
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
          
endmodule // se$wes$38


module se$wes$39(d,q,clock);
    
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
          
endmodule // se$wes$39


module se$wes$4(d,q,clock);
    
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
          
endmodule // se$wes$4


module se$wes$40(d,q,clock);
    
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
          
endmodule // se$wes$40


module se$wes$41(d,q,clock);
    
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
          
endmodule // se$wes$41


module se$wes$42(d,q,clock);
    
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
          
endmodule // se$wes$42


module se$wes$43(d,q,clock);
    
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
          
endmodule // se$wes$43


module se$wes$44(d,q,clock);
    
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
          
endmodule // se$wes$44


module se$wes$45(d,q,clock);
    
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
          
endmodule // se$wes$45


module se$wes$46(d,q,clock);
    
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
          
endmodule // se$wes$46


module se$wes$47(d,q,clock);
    
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
          
endmodule // se$wes$47


module se$wes$48(d,q,clock);
    
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
          
endmodule // se$wes$48


module se$wes$49(d,q,clock);
    
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
          
endmodule // se$wes$49


module se$wes$5(d,q,clock);
    
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
          
endmodule // se$wes$5


module se$wes$50(d,q,clock);
    
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
          
endmodule // se$wes$50


module se$wes$51(d,q,clock);
    
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
          
endmodule // se$wes$51


module se$wes$52(d,q,clock);
    
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
          
endmodule // se$wes$52


module se$wes$53(d,q,clock);
    
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
          
endmodule // se$wes$53


module se$wes$54(d,q,clock);
    
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
          
endmodule // se$wes$54


module se$wes$55(d,q,clock);
    
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
          
endmodule // se$wes$55


module se$wes$56(d,q,clock);
    
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
          
endmodule // se$wes$56


module se$wes$57(d,q,clock);
    
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
          
endmodule // se$wes$57


module se$wes$58(d,q,clock);
    
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
          
endmodule // se$wes$58


module se$wes$59(d,q,clock);
    
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
          
endmodule // se$wes$59


module se$wes$6(d,q,clock);
    
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
          
endmodule // se$wes$6


module se$wes$60(d,q,clock);
    
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
          
endmodule // se$wes$60


module se$wes$61(d,q,clock);
    
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
          
endmodule // se$wes$61


module se$wes$62(d,q,clock);
    
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
          
endmodule // se$wes$62


module se$wes$63(d,q,clock);
    
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
          
endmodule // se$wes$63


module se$wes$7(d,q,clock);
    
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
          
endmodule // se$wes$7


module se$wes$8(d,q,clock);
    
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
          
endmodule // se$wes$8


module se$wes$9(d,q,clock);
    
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
          
endmodule // se$wes$9


module se$zc$0(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$0$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$0


module se$zc$0$flag(d,q,clock);
    
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
          
endmodule // se$zc$0$flag


module se$zc$1(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$1$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$1


module se$zc$1$flag(d,q,clock);
    
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
          
endmodule // se$zc$1$flag


module se$zc$10(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$10$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$10


module se$zc$10$flag(d,q,clock);
    
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
          
endmodule // se$zc$10$flag


module se$zc$11(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$11$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$11


module se$zc$11$flag(d,q,clock);
    
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
          
endmodule // se$zc$11$flag


module se$zc$12(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$12$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$12


module se$zc$12$flag(d,q,clock);
    
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
          
endmodule // se$zc$12$flag


module se$zc$13(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$13$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$13


module se$zc$13$flag(d,q,clock);
    
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
          
endmodule // se$zc$13$flag


module se$zc$14(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$14$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$14


module se$zc$14$flag(d,q,clock);
    
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
          
endmodule // se$zc$14$flag


module se$zc$15(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$15$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$15


module se$zc$15$flag(d,q,clock);
    
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
          
endmodule // se$zc$15$flag


module se$zc$16(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$16$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$16


module se$zc$16$flag(d,q,clock);
    
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
          
endmodule // se$zc$16$flag


module se$zc$17(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$17$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$17


module se$zc$17$flag(d,q,clock);
    
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
          
endmodule // se$zc$17$flag


module se$zc$18(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$18$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$18


module se$zc$18$flag(d,q,clock);
    
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
          
endmodule // se$zc$18$flag


module se$zc$19(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$19$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$19


module se$zc$19$flag(d,q,clock);
    
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
          
endmodule // se$zc$19$flag


module se$zc$2(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$2$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$2


module se$zc$2$flag(d,q,clock);
    
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
          
endmodule // se$zc$2$flag


module se$zc$20(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$20$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$20


module se$zc$20$flag(d,q,clock);
    
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
          
endmodule // se$zc$20$flag


module se$zc$21(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$21$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$21


module se$zc$21$flag(d,q,clock);
    
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
          
endmodule // se$zc$21$flag


module se$zc$22(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$22$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$22


module se$zc$22$flag(d,q,clock);
    
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
          
endmodule // se$zc$22$flag


module se$zc$23(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$23$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$23


module se$zc$23$flag(d,q,clock);
    
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
          
endmodule // se$zc$23$flag


module se$zc$24(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$24$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$24


module se$zc$24$flag(d,q,clock);
    
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
          
endmodule // se$zc$24$flag


module se$zc$25(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$25$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$25


module se$zc$25$flag(d,q,clock);
    
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
          
endmodule // se$zc$25$flag


module se$zc$26(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$26$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$26


module se$zc$26$flag(d,q,clock);
    
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
          
endmodule // se$zc$26$flag


module se$zc$27(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$27$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$27


module se$zc$27$flag(d,q,clock);
    
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
          
endmodule // se$zc$27$flag


module se$zc$28(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$28$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$28


module se$zc$28$flag(d,q,clock);
    
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
          
endmodule // se$zc$28$flag


module se$zc$29(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$29$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$29


module se$zc$29$flag(d,q,clock);
    
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
          
endmodule // se$zc$29$flag


module se$zc$3(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$3$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$3


module se$zc$3$flag(d,q,clock);
    
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
          
endmodule // se$zc$3$flag


module se$zc$30(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$30$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$30


module se$zc$30$flag(d,q,clock);
    
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
          
endmodule // se$zc$30$flag


module se$zc$31(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$31$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$31


module se$zc$31$flag(d,q,clock);
    
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
          
endmodule // se$zc$31$flag


module se$zc$32(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$32$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$32


module se$zc$32$flag(d,q,clock);
    
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
          
endmodule // se$zc$32$flag


module se$zc$33(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$33$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$33


module se$zc$33$flag(d,q,clock);
    
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
          
endmodule // se$zc$33$flag


module se$zc$34(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$34$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$34


module se$zc$34$flag(d,q,clock);
    
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
          
endmodule // se$zc$34$flag


module se$zc$35(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$35$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$35


module se$zc$35$flag(d,q,clock);
    
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
          
endmodule // se$zc$35$flag


module se$zc$36(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$36$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$36


module se$zc$36$flag(d,q,clock);
    
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
          
endmodule // se$zc$36$flag


module se$zc$37(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$37$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$37


module se$zc$37$flag(d,q,clock);
    
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
          
endmodule // se$zc$37$flag


module se$zc$38(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$38$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$38


module se$zc$38$flag(d,q,clock);
    
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
          
endmodule // se$zc$38$flag


module se$zc$39(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$39$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$39


module se$zc$39$flag(d,q,clock);
    
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
          
endmodule // se$zc$39$flag


module se$zc$4(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$4$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$4


module se$zc$4$flag(d,q,clock);
    
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
          
endmodule // se$zc$4$flag


module se$zc$40(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$40$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$40


module se$zc$40$flag(d,q,clock);
    
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
          
endmodule // se$zc$40$flag


module se$zc$41(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$41$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$41


module se$zc$41$flag(d,q,clock);
    
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
          
endmodule // se$zc$41$flag


module se$zc$42(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$42$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$42


module se$zc$42$flag(d,q,clock);
    
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
          
endmodule // se$zc$42$flag


module se$zc$43(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$43$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$43


module se$zc$43$flag(d,q,clock);
    
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
          
endmodule // se$zc$43$flag


module se$zc$44(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$44$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$44


module se$zc$44$flag(d,q,clock);
    
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
          
endmodule // se$zc$44$flag


module se$zc$45(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$45$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$45


module se$zc$45$flag(d,q,clock);
    
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
          
endmodule // se$zc$45$flag


module se$zc$46(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$46$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$46


module se$zc$46$flag(d,q,clock);
    
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
          
endmodule // se$zc$46$flag


module se$zc$47(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$47$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$47


module se$zc$47$flag(d,q,clock);
    
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
          
endmodule // se$zc$47$flag


module se$zc$48(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$48$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$48


module se$zc$48$flag(d,q,clock);
    
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
          
endmodule // se$zc$48$flag


module se$zc$49(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$49$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$49


module se$zc$49$flag(d,q,clock);
    
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
          
endmodule // se$zc$49$flag


module se$zc$5(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$5$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$5


module se$zc$5$flag(d,q,clock);
    
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
          
endmodule // se$zc$5$flag


module se$zc$50(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$50$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$50


module se$zc$50$flag(d,q,clock);
    
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
          
endmodule // se$zc$50$flag


module se$zc$51(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$51$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$51


module se$zc$51$flag(d,q,clock);
    
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
          
endmodule // se$zc$51$flag


module se$zc$52(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$52$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$52


module se$zc$52$flag(d,q,clock);
    
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
          
endmodule // se$zc$52$flag


module se$zc$53(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$53$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$53


module se$zc$53$flag(d,q,clock);
    
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
          
endmodule // se$zc$53$flag


module se$zc$54(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$54$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$54


module se$zc$54$flag(d,q,clock);
    
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
          
endmodule // se$zc$54$flag


module se$zc$55(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$55$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$55


module se$zc$55$flag(d,q,clock);
    
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
          
endmodule // se$zc$55$flag


module se$zc$56(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$56$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$56


module se$zc$56$flag(d,q,clock);
    
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
          
endmodule // se$zc$56$flag


module se$zc$57(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$57$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$57


module se$zc$57$flag(d,q,clock);
    
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
          
endmodule // se$zc$57$flag


module se$zc$58(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$58$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$58


module se$zc$58$flag(d,q,clock);
    
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
          
endmodule // se$zc$58$flag


module se$zc$59(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$59$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$59


module se$zc$59$flag(d,q,clock);
    
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
          
endmodule // se$zc$59$flag


module se$zc$6(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$6$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$6


module se$zc$6$flag(d,q,clock);
    
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
          
endmodule // se$zc$6$flag


module se$zc$60(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$60$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$60


module se$zc$60$flag(d,q,clock);
    
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
          
endmodule // se$zc$60$flag


module se$zc$61(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$61$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$61


module se$zc$61$flag(d,q,clock);
    
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
          
endmodule // se$zc$61$flag


module se$zc$62(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$62$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$62


module se$zc$62$flag(d,q,clock);
    
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
          
endmodule // se$zc$62$flag


module se$zc$63(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$63$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$63


module se$zc$63$flag(d,q,clock);
    
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
          
endmodule // se$zc$63$flag


module se$zc$7(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$7$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$7


module se$zc$7$flag(d,q,clock);
    
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
          
endmodule // se$zc$7$flag


module se$zc$8(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$8$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$8


module se$zc$8$flag(d,q,clock);
    
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
          
endmodule // se$zc$8$flag


module se$zc$9(clock,first,nz,oz,closer);
    
    // Module arguments
    input wire  clock;
    input wire  first;
    input wire  nz;
    input wire  oz;
    output reg  closer;
    
    // Stub signals
    reg  flag$d;
    wire  flag$q;
    reg  flag$clock;
    
    // Local signals
    reg  held;
    
    // Sub module instances
    se$zc$9$flag flag(
        .d(flag$d),
        .q(flag$q),
        .clock(flag$clock)
    );
    
    // Update code
    always @(*) begin
        flag$clock = clock;
        flag$d = flag$q;
        held = flag$q & ~first;
        flag$d = held;
        if (nz != oz) begin
            flag$d = oz;
        end
        closer = flag$q;
    end
    
endmodule // se$zc$9


module se$zc$9$flag(d,q,clock);
    
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
          
endmodule // se$zc$9$flag
