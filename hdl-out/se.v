

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
    localparam  k_zmsb = 24'h800000;
    localparam  k_cmsb = 16'h8000;
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
    reg  [23:0] ozr$0$d;
    wire  [23:0] ozr$0$q;
    reg  ozr$0$clock;
    reg  [23:0] ozr$1$d;
    wire  [23:0] ozr$1$q;
    reg  ozr$1$clock;
    reg  [23:0] ozr$2$d;
    wire  [23:0] ozr$2$q;
    reg  ozr$2$clock;
    reg  [23:0] ozr$3$d;
    wire  [23:0] ozr$3$q;
    reg  ozr$3$clock;
    reg  [23:0] ozr$4$d;
    wire  [23:0] ozr$4$q;
    reg  ozr$4$clock;
    reg  [23:0] ozr$5$d;
    wire  [23:0] ozr$5$q;
    reg  ozr$5$clock;
    reg  [23:0] ozr$6$d;
    wire  [23:0] ozr$6$q;
    reg  ozr$6$clock;
    reg  [23:0] ozr$7$d;
    wire  [23:0] ozr$7$q;
    reg  ozr$7$clock;
    reg  [23:0] ozr$8$d;
    wire  [23:0] ozr$8$q;
    reg  ozr$8$clock;
    reg  [23:0] ozr$9$d;
    wire  [23:0] ozr$9$q;
    reg  ozr$9$clock;
    reg  [23:0] ozr$10$d;
    wire  [23:0] ozr$10$q;
    reg  ozr$10$clock;
    reg  [23:0] ozr$11$d;
    wire  [23:0] ozr$11$q;
    reg  ozr$11$clock;
    reg  [23:0] ozr$12$d;
    wire  [23:0] ozr$12$q;
    reg  ozr$12$clock;
    reg  [23:0] ozr$13$d;
    wire  [23:0] ozr$13$q;
    reg  ozr$13$clock;
    reg  [23:0] ozr$14$d;
    wire  [23:0] ozr$14$q;
    reg  ozr$14$clock;
    reg  [23:0] ozr$15$d;
    wire  [23:0] ozr$15$q;
    reg  ozr$15$clock;
    reg  [23:0] ozr$16$d;
    wire  [23:0] ozr$16$q;
    reg  ozr$16$clock;
    reg  [23:0] ozr$17$d;
    wire  [23:0] ozr$17$q;
    reg  ozr$17$clock;
    reg  [23:0] ozr$18$d;
    wire  [23:0] ozr$18$q;
    reg  ozr$18$clock;
    reg  [23:0] ozr$19$d;
    wire  [23:0] ozr$19$q;
    reg  ozr$19$clock;
    reg  [23:0] ozr$20$d;
    wire  [23:0] ozr$20$q;
    reg  ozr$20$clock;
    reg  [23:0] ozr$21$d;
    wire  [23:0] ozr$21$q;
    reg  ozr$21$clock;
    reg  [23:0] ozr$22$d;
    wire  [23:0] ozr$22$q;
    reg  ozr$22$clock;
    reg  [23:0] ozr$23$d;
    wire  [23:0] ozr$23$q;
    reg  ozr$23$clock;
    reg  [23:0] ozr$24$d;
    wire  [23:0] ozr$24$q;
    reg  ozr$24$clock;
    reg  [23:0] ozr$25$d;
    wire  [23:0] ozr$25$q;
    reg  ozr$25$clock;
    reg  [23:0] ozr$26$d;
    wire  [23:0] ozr$26$q;
    reg  ozr$26$clock;
    reg  [23:0] ozr$27$d;
    wire  [23:0] ozr$27$q;
    reg  ozr$27$clock;
    reg  [23:0] ozr$28$d;
    wire  [23:0] ozr$28$q;
    reg  ozr$28$clock;
    reg  [23:0] ozr$29$d;
    wire  [23:0] ozr$29$q;
    reg  ozr$29$clock;
    reg  [23:0] ozr$30$d;
    wire  [23:0] ozr$30$q;
    reg  ozr$30$clock;
    reg  [23:0] ozr$31$d;
    wire  [23:0] ozr$31$q;
    reg  ozr$31$clock;
    reg  [23:0] ozr$32$d;
    wire  [23:0] ozr$32$q;
    reg  ozr$32$clock;
    reg  [23:0] ozr$33$d;
    wire  [23:0] ozr$33$q;
    reg  ozr$33$clock;
    reg  [23:0] ozr$34$d;
    wire  [23:0] ozr$34$q;
    reg  ozr$34$clock;
    reg  [23:0] ozr$35$d;
    wire  [23:0] ozr$35$q;
    reg  ozr$35$clock;
    reg  [23:0] ozr$36$d;
    wire  [23:0] ozr$36$q;
    reg  ozr$36$clock;
    reg  [23:0] ozr$37$d;
    wire  [23:0] ozr$37$q;
    reg  ozr$37$clock;
    reg  [23:0] ozr$38$d;
    wire  [23:0] ozr$38$q;
    reg  ozr$38$clock;
    reg  [23:0] ozr$39$d;
    wire  [23:0] ozr$39$q;
    reg  ozr$39$clock;
    reg  [23:0] ozr$40$d;
    wire  [23:0] ozr$40$q;
    reg  ozr$40$clock;
    reg  [23:0] ozr$41$d;
    wire  [23:0] ozr$41$q;
    reg  ozr$41$clock;
    reg  [23:0] ozr$42$d;
    wire  [23:0] ozr$42$q;
    reg  ozr$42$clock;
    reg  [23:0] ozr$43$d;
    wire  [23:0] ozr$43$q;
    reg  ozr$43$clock;
    reg  [23:0] ozr$44$d;
    wire  [23:0] ozr$44$q;
    reg  ozr$44$clock;
    reg  [23:0] ozr$45$d;
    wire  [23:0] ozr$45$q;
    reg  ozr$45$clock;
    reg  [23:0] ozr$46$d;
    wire  [23:0] ozr$46$q;
    reg  ozr$46$clock;
    reg  [23:0] ozr$47$d;
    wire  [23:0] ozr$47$q;
    reg  ozr$47$clock;
    reg  [23:0] ozr$48$d;
    wire  [23:0] ozr$48$q;
    reg  ozr$48$clock;
    reg  [23:0] ozr$49$d;
    wire  [23:0] ozr$49$q;
    reg  ozr$49$clock;
    reg  [23:0] ozr$50$d;
    wire  [23:0] ozr$50$q;
    reg  ozr$50$clock;
    reg  [23:0] ozr$51$d;
    wire  [23:0] ozr$51$q;
    reg  ozr$51$clock;
    reg  [23:0] ozr$52$d;
    wire  [23:0] ozr$52$q;
    reg  ozr$52$clock;
    reg  [23:0] ozr$53$d;
    wire  [23:0] ozr$53$q;
    reg  ozr$53$clock;
    reg  [23:0] ozr$54$d;
    wire  [23:0] ozr$54$q;
    reg  ozr$54$clock;
    reg  [23:0] ozr$55$d;
    wire  [23:0] ozr$55$q;
    reg  ozr$55$clock;
    reg  [23:0] ozr$56$d;
    wire  [23:0] ozr$56$q;
    reg  ozr$56$clock;
    reg  [23:0] ozr$57$d;
    wire  [23:0] ozr$57$q;
    reg  ozr$57$clock;
    reg  [23:0] ozr$58$d;
    wire  [23:0] ozr$58$q;
    reg  ozr$58$clock;
    reg  [23:0] ozr$59$d;
    wire  [23:0] ozr$59$q;
    reg  ozr$59$clock;
    reg  [23:0] ozr$60$d;
    wire  [23:0] ozr$60$q;
    reg  ozr$60$clock;
    reg  [23:0] ozr$61$d;
    wire  [23:0] ozr$61$q;
    reg  ozr$61$clock;
    reg  [23:0] ozr$62$d;
    wire  [23:0] ozr$62$q;
    reg  ozr$62$clock;
    reg  [23:0] ozr$63$d;
    wire  [23:0] ozr$63$q;
    reg  ozr$63$clock;
    reg  [23:0] nzr$0$d;
    wire  [23:0] nzr$0$q;
    reg  nzr$0$clock;
    reg  [23:0] nzr$1$d;
    wire  [23:0] nzr$1$q;
    reg  nzr$1$clock;
    reg  [23:0] nzr$2$d;
    wire  [23:0] nzr$2$q;
    reg  nzr$2$clock;
    reg  [23:0] nzr$3$d;
    wire  [23:0] nzr$3$q;
    reg  nzr$3$clock;
    reg  [23:0] nzr$4$d;
    wire  [23:0] nzr$4$q;
    reg  nzr$4$clock;
    reg  [23:0] nzr$5$d;
    wire  [23:0] nzr$5$q;
    reg  nzr$5$clock;
    reg  [23:0] nzr$6$d;
    wire  [23:0] nzr$6$q;
    reg  nzr$6$clock;
    reg  [23:0] nzr$7$d;
    wire  [23:0] nzr$7$q;
    reg  nzr$7$clock;
    reg  [23:0] nzr$8$d;
    wire  [23:0] nzr$8$q;
    reg  nzr$8$clock;
    reg  [23:0] nzr$9$d;
    wire  [23:0] nzr$9$q;
    reg  nzr$9$clock;
    reg  [23:0] nzr$10$d;
    wire  [23:0] nzr$10$q;
    reg  nzr$10$clock;
    reg  [23:0] nzr$11$d;
    wire  [23:0] nzr$11$q;
    reg  nzr$11$clock;
    reg  [23:0] nzr$12$d;
    wire  [23:0] nzr$12$q;
    reg  nzr$12$clock;
    reg  [23:0] nzr$13$d;
    wire  [23:0] nzr$13$q;
    reg  nzr$13$clock;
    reg  [23:0] nzr$14$d;
    wire  [23:0] nzr$14$q;
    reg  nzr$14$clock;
    reg  [23:0] nzr$15$d;
    wire  [23:0] nzr$15$q;
    reg  nzr$15$clock;
    reg  [23:0] nzr$16$d;
    wire  [23:0] nzr$16$q;
    reg  nzr$16$clock;
    reg  [23:0] nzr$17$d;
    wire  [23:0] nzr$17$q;
    reg  nzr$17$clock;
    reg  [23:0] nzr$18$d;
    wire  [23:0] nzr$18$q;
    reg  nzr$18$clock;
    reg  [23:0] nzr$19$d;
    wire  [23:0] nzr$19$q;
    reg  nzr$19$clock;
    reg  [23:0] nzr$20$d;
    wire  [23:0] nzr$20$q;
    reg  nzr$20$clock;
    reg  [23:0] nzr$21$d;
    wire  [23:0] nzr$21$q;
    reg  nzr$21$clock;
    reg  [23:0] nzr$22$d;
    wire  [23:0] nzr$22$q;
    reg  nzr$22$clock;
    reg  [23:0] nzr$23$d;
    wire  [23:0] nzr$23$q;
    reg  nzr$23$clock;
    reg  [23:0] nzr$24$d;
    wire  [23:0] nzr$24$q;
    reg  nzr$24$clock;
    reg  [23:0] nzr$25$d;
    wire  [23:0] nzr$25$q;
    reg  nzr$25$clock;
    reg  [23:0] nzr$26$d;
    wire  [23:0] nzr$26$q;
    reg  nzr$26$clock;
    reg  [23:0] nzr$27$d;
    wire  [23:0] nzr$27$q;
    reg  nzr$27$clock;
    reg  [23:0] nzr$28$d;
    wire  [23:0] nzr$28$q;
    reg  nzr$28$clock;
    reg  [23:0] nzr$29$d;
    wire  [23:0] nzr$29$q;
    reg  nzr$29$clock;
    reg  [23:0] nzr$30$d;
    wire  [23:0] nzr$30$q;
    reg  nzr$30$clock;
    reg  [23:0] nzr$31$d;
    wire  [23:0] nzr$31$q;
    reg  nzr$31$clock;
    reg  [23:0] nzr$32$d;
    wire  [23:0] nzr$32$q;
    reg  nzr$32$clock;
    reg  [23:0] nzr$33$d;
    wire  [23:0] nzr$33$q;
    reg  nzr$33$clock;
    reg  [23:0] nzr$34$d;
    wire  [23:0] nzr$34$q;
    reg  nzr$34$clock;
    reg  [23:0] nzr$35$d;
    wire  [23:0] nzr$35$q;
    reg  nzr$35$clock;
    reg  [23:0] nzr$36$d;
    wire  [23:0] nzr$36$q;
    reg  nzr$36$clock;
    reg  [23:0] nzr$37$d;
    wire  [23:0] nzr$37$q;
    reg  nzr$37$clock;
    reg  [23:0] nzr$38$d;
    wire  [23:0] nzr$38$q;
    reg  nzr$38$clock;
    reg  [23:0] nzr$39$d;
    wire  [23:0] nzr$39$q;
    reg  nzr$39$clock;
    reg  [23:0] nzr$40$d;
    wire  [23:0] nzr$40$q;
    reg  nzr$40$clock;
    reg  [23:0] nzr$41$d;
    wire  [23:0] nzr$41$q;
    reg  nzr$41$clock;
    reg  [23:0] nzr$42$d;
    wire  [23:0] nzr$42$q;
    reg  nzr$42$clock;
    reg  [23:0] nzr$43$d;
    wire  [23:0] nzr$43$q;
    reg  nzr$43$clock;
    reg  [23:0] nzr$44$d;
    wire  [23:0] nzr$44$q;
    reg  nzr$44$clock;
    reg  [23:0] nzr$45$d;
    wire  [23:0] nzr$45$q;
    reg  nzr$45$clock;
    reg  [23:0] nzr$46$d;
    wire  [23:0] nzr$46$q;
    reg  nzr$46$clock;
    reg  [23:0] nzr$47$d;
    wire  [23:0] nzr$47$q;
    reg  nzr$47$clock;
    reg  [23:0] nzr$48$d;
    wire  [23:0] nzr$48$q;
    reg  nzr$48$clock;
    reg  [23:0] nzr$49$d;
    wire  [23:0] nzr$49$q;
    reg  nzr$49$clock;
    reg  [23:0] nzr$50$d;
    wire  [23:0] nzr$50$q;
    reg  nzr$50$clock;
    reg  [23:0] nzr$51$d;
    wire  [23:0] nzr$51$q;
    reg  nzr$51$clock;
    reg  [23:0] nzr$52$d;
    wire  [23:0] nzr$52$q;
    reg  nzr$52$clock;
    reg  [23:0] nzr$53$d;
    wire  [23:0] nzr$53$q;
    reg  nzr$53$clock;
    reg  [23:0] nzr$54$d;
    wire  [23:0] nzr$54$q;
    reg  nzr$54$clock;
    reg  [23:0] nzr$55$d;
    wire  [23:0] nzr$55$q;
    reg  nzr$55$clock;
    reg  [23:0] nzr$56$d;
    wire  [23:0] nzr$56$q;
    reg  nzr$56$clock;
    reg  [23:0] nzr$57$d;
    wire  [23:0] nzr$57$q;
    reg  nzr$57$clock;
    reg  [23:0] nzr$58$d;
    wire  [23:0] nzr$58$q;
    reg  nzr$58$clock;
    reg  [23:0] nzr$59$d;
    wire  [23:0] nzr$59$q;
    reg  nzr$59$clock;
    reg  [23:0] nzr$60$d;
    wire  [23:0] nzr$60$q;
    reg  nzr$60$clock;
    reg  [23:0] nzr$61$d;
    wire  [23:0] nzr$61$q;
    reg  nzr$61$clock;
    reg  [23:0] nzr$62$d;
    wire  [23:0] nzr$62$q;
    reg  nzr$62$clock;
    reg  [23:0] nzr$63$d;
    wire  [23:0] nzr$63$q;
    reg  nzr$63$clock;
    reg  [15:0] rr$0$d;
    wire  [15:0] rr$0$q;
    reg  rr$0$clock;
    reg  [15:0] rr$1$d;
    wire  [15:0] rr$1$q;
    reg  rr$1$clock;
    reg  [15:0] rr$2$d;
    wire  [15:0] rr$2$q;
    reg  rr$2$clock;
    reg  [15:0] rr$3$d;
    wire  [15:0] rr$3$q;
    reg  rr$3$clock;
    reg  [15:0] rr$4$d;
    wire  [15:0] rr$4$q;
    reg  rr$4$clock;
    reg  [15:0] rr$5$d;
    wire  [15:0] rr$5$q;
    reg  rr$5$clock;
    reg  [15:0] rr$6$d;
    wire  [15:0] rr$6$q;
    reg  rr$6$clock;
    reg  [15:0] rr$7$d;
    wire  [15:0] rr$7$q;
    reg  rr$7$clock;
    reg  [15:0] rr$8$d;
    wire  [15:0] rr$8$q;
    reg  rr$8$clock;
    reg  [15:0] rr$9$d;
    wire  [15:0] rr$9$q;
    reg  rr$9$clock;
    reg  [15:0] rr$10$d;
    wire  [15:0] rr$10$q;
    reg  rr$10$clock;
    reg  [15:0] rr$11$d;
    wire  [15:0] rr$11$q;
    reg  rr$11$clock;
    reg  [15:0] rr$12$d;
    wire  [15:0] rr$12$q;
    reg  rr$12$clock;
    reg  [15:0] rr$13$d;
    wire  [15:0] rr$13$q;
    reg  rr$13$clock;
    reg  [15:0] rr$14$d;
    wire  [15:0] rr$14$q;
    reg  rr$14$clock;
    reg  [15:0] rr$15$d;
    wire  [15:0] rr$15$q;
    reg  rr$15$clock;
    reg  [15:0] rr$16$d;
    wire  [15:0] rr$16$q;
    reg  rr$16$clock;
    reg  [15:0] rr$17$d;
    wire  [15:0] rr$17$q;
    reg  rr$17$clock;
    reg  [15:0] rr$18$d;
    wire  [15:0] rr$18$q;
    reg  rr$18$clock;
    reg  [15:0] rr$19$d;
    wire  [15:0] rr$19$q;
    reg  rr$19$clock;
    reg  [15:0] rr$20$d;
    wire  [15:0] rr$20$q;
    reg  rr$20$clock;
    reg  [15:0] rr$21$d;
    wire  [15:0] rr$21$q;
    reg  rr$21$clock;
    reg  [15:0] rr$22$d;
    wire  [15:0] rr$22$q;
    reg  rr$22$clock;
    reg  [15:0] rr$23$d;
    wire  [15:0] rr$23$q;
    reg  rr$23$clock;
    reg  [15:0] rr$24$d;
    wire  [15:0] rr$24$q;
    reg  rr$24$clock;
    reg  [15:0] rr$25$d;
    wire  [15:0] rr$25$q;
    reg  rr$25$clock;
    reg  [15:0] rr$26$d;
    wire  [15:0] rr$26$q;
    reg  rr$26$clock;
    reg  [15:0] rr$27$d;
    wire  [15:0] rr$27$q;
    reg  rr$27$clock;
    reg  [15:0] rr$28$d;
    wire  [15:0] rr$28$q;
    reg  rr$28$clock;
    reg  [15:0] rr$29$d;
    wire  [15:0] rr$29$q;
    reg  rr$29$clock;
    reg  [15:0] rr$30$d;
    wire  [15:0] rr$30$q;
    reg  rr$30$clock;
    reg  [15:0] rr$31$d;
    wire  [15:0] rr$31$q;
    reg  rr$31$clock;
    reg  [15:0] rr$32$d;
    wire  [15:0] rr$32$q;
    reg  rr$32$clock;
    reg  [15:0] rr$33$d;
    wire  [15:0] rr$33$q;
    reg  rr$33$clock;
    reg  [15:0] rr$34$d;
    wire  [15:0] rr$34$q;
    reg  rr$34$clock;
    reg  [15:0] rr$35$d;
    wire  [15:0] rr$35$q;
    reg  rr$35$clock;
    reg  [15:0] rr$36$d;
    wire  [15:0] rr$36$q;
    reg  rr$36$clock;
    reg  [15:0] rr$37$d;
    wire  [15:0] rr$37$q;
    reg  rr$37$clock;
    reg  [15:0] rr$38$d;
    wire  [15:0] rr$38$q;
    reg  rr$38$clock;
    reg  [15:0] rr$39$d;
    wire  [15:0] rr$39$q;
    reg  rr$39$clock;
    reg  [15:0] rr$40$d;
    wire  [15:0] rr$40$q;
    reg  rr$40$clock;
    reg  [15:0] rr$41$d;
    wire  [15:0] rr$41$q;
    reg  rr$41$clock;
    reg  [15:0] rr$42$d;
    wire  [15:0] rr$42$q;
    reg  rr$42$clock;
    reg  [15:0] rr$43$d;
    wire  [15:0] rr$43$q;
    reg  rr$43$clock;
    reg  [15:0] rr$44$d;
    wire  [15:0] rr$44$q;
    reg  rr$44$clock;
    reg  [15:0] rr$45$d;
    wire  [15:0] rr$45$q;
    reg  rr$45$clock;
    reg  [15:0] rr$46$d;
    wire  [15:0] rr$46$q;
    reg  rr$46$clock;
    reg  [15:0] rr$47$d;
    wire  [15:0] rr$47$q;
    reg  rr$47$clock;
    reg  [15:0] rr$48$d;
    wire  [15:0] rr$48$q;
    reg  rr$48$clock;
    reg  [15:0] rr$49$d;
    wire  [15:0] rr$49$q;
    reg  rr$49$clock;
    reg  [15:0] rr$50$d;
    wire  [15:0] rr$50$q;
    reg  rr$50$clock;
    reg  [15:0] rr$51$d;
    wire  [15:0] rr$51$q;
    reg  rr$51$clock;
    reg  [15:0] rr$52$d;
    wire  [15:0] rr$52$q;
    reg  rr$52$clock;
    reg  [15:0] rr$53$d;
    wire  [15:0] rr$53$q;
    reg  rr$53$clock;
    reg  [15:0] rr$54$d;
    wire  [15:0] rr$54$q;
    reg  rr$54$clock;
    reg  [15:0] rr$55$d;
    wire  [15:0] rr$55$q;
    reg  rr$55$clock;
    reg  [15:0] rr$56$d;
    wire  [15:0] rr$56$q;
    reg  rr$56$clock;
    reg  [15:0] rr$57$d;
    wire  [15:0] rr$57$q;
    reg  rr$57$clock;
    reg  [15:0] rr$58$d;
    wire  [15:0] rr$58$q;
    reg  rr$58$clock;
    reg  [15:0] rr$59$d;
    wire  [15:0] rr$59$q;
    reg  rr$59$clock;
    reg  [15:0] rr$60$d;
    wire  [15:0] rr$60$q;
    reg  rr$60$clock;
    reg  [15:0] rr$61$d;
    wire  [15:0] rr$61$q;
    reg  rr$61$clock;
    reg  [15:0] rr$62$d;
    wire  [15:0] rr$62$q;
    reg  rr$62$clock;
    reg  [15:0] rr$63$d;
    wire  [15:0] rr$63$q;
    reg  rr$63$clock;
    reg  [15:0] gr$0$d;
    wire  [15:0] gr$0$q;
    reg  gr$0$clock;
    reg  [15:0] gr$1$d;
    wire  [15:0] gr$1$q;
    reg  gr$1$clock;
    reg  [15:0] gr$2$d;
    wire  [15:0] gr$2$q;
    reg  gr$2$clock;
    reg  [15:0] gr$3$d;
    wire  [15:0] gr$3$q;
    reg  gr$3$clock;
    reg  [15:0] gr$4$d;
    wire  [15:0] gr$4$q;
    reg  gr$4$clock;
    reg  [15:0] gr$5$d;
    wire  [15:0] gr$5$q;
    reg  gr$5$clock;
    reg  [15:0] gr$6$d;
    wire  [15:0] gr$6$q;
    reg  gr$6$clock;
    reg  [15:0] gr$7$d;
    wire  [15:0] gr$7$q;
    reg  gr$7$clock;
    reg  [15:0] gr$8$d;
    wire  [15:0] gr$8$q;
    reg  gr$8$clock;
    reg  [15:0] gr$9$d;
    wire  [15:0] gr$9$q;
    reg  gr$9$clock;
    reg  [15:0] gr$10$d;
    wire  [15:0] gr$10$q;
    reg  gr$10$clock;
    reg  [15:0] gr$11$d;
    wire  [15:0] gr$11$q;
    reg  gr$11$clock;
    reg  [15:0] gr$12$d;
    wire  [15:0] gr$12$q;
    reg  gr$12$clock;
    reg  [15:0] gr$13$d;
    wire  [15:0] gr$13$q;
    reg  gr$13$clock;
    reg  [15:0] gr$14$d;
    wire  [15:0] gr$14$q;
    reg  gr$14$clock;
    reg  [15:0] gr$15$d;
    wire  [15:0] gr$15$q;
    reg  gr$15$clock;
    reg  [15:0] gr$16$d;
    wire  [15:0] gr$16$q;
    reg  gr$16$clock;
    reg  [15:0] gr$17$d;
    wire  [15:0] gr$17$q;
    reg  gr$17$clock;
    reg  [15:0] gr$18$d;
    wire  [15:0] gr$18$q;
    reg  gr$18$clock;
    reg  [15:0] gr$19$d;
    wire  [15:0] gr$19$q;
    reg  gr$19$clock;
    reg  [15:0] gr$20$d;
    wire  [15:0] gr$20$q;
    reg  gr$20$clock;
    reg  [15:0] gr$21$d;
    wire  [15:0] gr$21$q;
    reg  gr$21$clock;
    reg  [15:0] gr$22$d;
    wire  [15:0] gr$22$q;
    reg  gr$22$clock;
    reg  [15:0] gr$23$d;
    wire  [15:0] gr$23$q;
    reg  gr$23$clock;
    reg  [15:0] gr$24$d;
    wire  [15:0] gr$24$q;
    reg  gr$24$clock;
    reg  [15:0] gr$25$d;
    wire  [15:0] gr$25$q;
    reg  gr$25$clock;
    reg  [15:0] gr$26$d;
    wire  [15:0] gr$26$q;
    reg  gr$26$clock;
    reg  [15:0] gr$27$d;
    wire  [15:0] gr$27$q;
    reg  gr$27$clock;
    reg  [15:0] gr$28$d;
    wire  [15:0] gr$28$q;
    reg  gr$28$clock;
    reg  [15:0] gr$29$d;
    wire  [15:0] gr$29$q;
    reg  gr$29$clock;
    reg  [15:0] gr$30$d;
    wire  [15:0] gr$30$q;
    reg  gr$30$clock;
    reg  [15:0] gr$31$d;
    wire  [15:0] gr$31$q;
    reg  gr$31$clock;
    reg  [15:0] gr$32$d;
    wire  [15:0] gr$32$q;
    reg  gr$32$clock;
    reg  [15:0] gr$33$d;
    wire  [15:0] gr$33$q;
    reg  gr$33$clock;
    reg  [15:0] gr$34$d;
    wire  [15:0] gr$34$q;
    reg  gr$34$clock;
    reg  [15:0] gr$35$d;
    wire  [15:0] gr$35$q;
    reg  gr$35$clock;
    reg  [15:0] gr$36$d;
    wire  [15:0] gr$36$q;
    reg  gr$36$clock;
    reg  [15:0] gr$37$d;
    wire  [15:0] gr$37$q;
    reg  gr$37$clock;
    reg  [15:0] gr$38$d;
    wire  [15:0] gr$38$q;
    reg  gr$38$clock;
    reg  [15:0] gr$39$d;
    wire  [15:0] gr$39$q;
    reg  gr$39$clock;
    reg  [15:0] gr$40$d;
    wire  [15:0] gr$40$q;
    reg  gr$40$clock;
    reg  [15:0] gr$41$d;
    wire  [15:0] gr$41$q;
    reg  gr$41$clock;
    reg  [15:0] gr$42$d;
    wire  [15:0] gr$42$q;
    reg  gr$42$clock;
    reg  [15:0] gr$43$d;
    wire  [15:0] gr$43$q;
    reg  gr$43$clock;
    reg  [15:0] gr$44$d;
    wire  [15:0] gr$44$q;
    reg  gr$44$clock;
    reg  [15:0] gr$45$d;
    wire  [15:0] gr$45$q;
    reg  gr$45$clock;
    reg  [15:0] gr$46$d;
    wire  [15:0] gr$46$q;
    reg  gr$46$clock;
    reg  [15:0] gr$47$d;
    wire  [15:0] gr$47$q;
    reg  gr$47$clock;
    reg  [15:0] gr$48$d;
    wire  [15:0] gr$48$q;
    reg  gr$48$clock;
    reg  [15:0] gr$49$d;
    wire  [15:0] gr$49$q;
    reg  gr$49$clock;
    reg  [15:0] gr$50$d;
    wire  [15:0] gr$50$q;
    reg  gr$50$clock;
    reg  [15:0] gr$51$d;
    wire  [15:0] gr$51$q;
    reg  gr$51$clock;
    reg  [15:0] gr$52$d;
    wire  [15:0] gr$52$q;
    reg  gr$52$clock;
    reg  [15:0] gr$53$d;
    wire  [15:0] gr$53$q;
    reg  gr$53$clock;
    reg  [15:0] gr$54$d;
    wire  [15:0] gr$54$q;
    reg  gr$54$clock;
    reg  [15:0] gr$55$d;
    wire  [15:0] gr$55$q;
    reg  gr$55$clock;
    reg  [15:0] gr$56$d;
    wire  [15:0] gr$56$q;
    reg  gr$56$clock;
    reg  [15:0] gr$57$d;
    wire  [15:0] gr$57$q;
    reg  gr$57$clock;
    reg  [15:0] gr$58$d;
    wire  [15:0] gr$58$q;
    reg  gr$58$clock;
    reg  [15:0] gr$59$d;
    wire  [15:0] gr$59$q;
    reg  gr$59$clock;
    reg  [15:0] gr$60$d;
    wire  [15:0] gr$60$q;
    reg  gr$60$clock;
    reg  [15:0] gr$61$d;
    wire  [15:0] gr$61$q;
    reg  gr$61$clock;
    reg  [15:0] gr$62$d;
    wire  [15:0] gr$62$q;
    reg  gr$62$clock;
    reg  [15:0] gr$63$d;
    wire  [15:0] gr$63$q;
    reg  gr$63$clock;
    reg  [15:0] br$0$d;
    wire  [15:0] br$0$q;
    reg  br$0$clock;
    reg  [15:0] br$1$d;
    wire  [15:0] br$1$q;
    reg  br$1$clock;
    reg  [15:0] br$2$d;
    wire  [15:0] br$2$q;
    reg  br$2$clock;
    reg  [15:0] br$3$d;
    wire  [15:0] br$3$q;
    reg  br$3$clock;
    reg  [15:0] br$4$d;
    wire  [15:0] br$4$q;
    reg  br$4$clock;
    reg  [15:0] br$5$d;
    wire  [15:0] br$5$q;
    reg  br$5$clock;
    reg  [15:0] br$6$d;
    wire  [15:0] br$6$q;
    reg  br$6$clock;
    reg  [15:0] br$7$d;
    wire  [15:0] br$7$q;
    reg  br$7$clock;
    reg  [15:0] br$8$d;
    wire  [15:0] br$8$q;
    reg  br$8$clock;
    reg  [15:0] br$9$d;
    wire  [15:0] br$9$q;
    reg  br$9$clock;
    reg  [15:0] br$10$d;
    wire  [15:0] br$10$q;
    reg  br$10$clock;
    reg  [15:0] br$11$d;
    wire  [15:0] br$11$q;
    reg  br$11$clock;
    reg  [15:0] br$12$d;
    wire  [15:0] br$12$q;
    reg  br$12$clock;
    reg  [15:0] br$13$d;
    wire  [15:0] br$13$q;
    reg  br$13$clock;
    reg  [15:0] br$14$d;
    wire  [15:0] br$14$q;
    reg  br$14$clock;
    reg  [15:0] br$15$d;
    wire  [15:0] br$15$q;
    reg  br$15$clock;
    reg  [15:0] br$16$d;
    wire  [15:0] br$16$q;
    reg  br$16$clock;
    reg  [15:0] br$17$d;
    wire  [15:0] br$17$q;
    reg  br$17$clock;
    reg  [15:0] br$18$d;
    wire  [15:0] br$18$q;
    reg  br$18$clock;
    reg  [15:0] br$19$d;
    wire  [15:0] br$19$q;
    reg  br$19$clock;
    reg  [15:0] br$20$d;
    wire  [15:0] br$20$q;
    reg  br$20$clock;
    reg  [15:0] br$21$d;
    wire  [15:0] br$21$q;
    reg  br$21$clock;
    reg  [15:0] br$22$d;
    wire  [15:0] br$22$q;
    reg  br$22$clock;
    reg  [15:0] br$23$d;
    wire  [15:0] br$23$q;
    reg  br$23$clock;
    reg  [15:0] br$24$d;
    wire  [15:0] br$24$q;
    reg  br$24$clock;
    reg  [15:0] br$25$d;
    wire  [15:0] br$25$q;
    reg  br$25$clock;
    reg  [15:0] br$26$d;
    wire  [15:0] br$26$q;
    reg  br$26$clock;
    reg  [15:0] br$27$d;
    wire  [15:0] br$27$q;
    reg  br$27$clock;
    reg  [15:0] br$28$d;
    wire  [15:0] br$28$q;
    reg  br$28$clock;
    reg  [15:0] br$29$d;
    wire  [15:0] br$29$q;
    reg  br$29$clock;
    reg  [15:0] br$30$d;
    wire  [15:0] br$30$q;
    reg  br$30$clock;
    reg  [15:0] br$31$d;
    wire  [15:0] br$31$q;
    reg  br$31$clock;
    reg  [15:0] br$32$d;
    wire  [15:0] br$32$q;
    reg  br$32$clock;
    reg  [15:0] br$33$d;
    wire  [15:0] br$33$q;
    reg  br$33$clock;
    reg  [15:0] br$34$d;
    wire  [15:0] br$34$q;
    reg  br$34$clock;
    reg  [15:0] br$35$d;
    wire  [15:0] br$35$q;
    reg  br$35$clock;
    reg  [15:0] br$36$d;
    wire  [15:0] br$36$q;
    reg  br$36$clock;
    reg  [15:0] br$37$d;
    wire  [15:0] br$37$q;
    reg  br$37$clock;
    reg  [15:0] br$38$d;
    wire  [15:0] br$38$q;
    reg  br$38$clock;
    reg  [15:0] br$39$d;
    wire  [15:0] br$39$q;
    reg  br$39$clock;
    reg  [15:0] br$40$d;
    wire  [15:0] br$40$q;
    reg  br$40$clock;
    reg  [15:0] br$41$d;
    wire  [15:0] br$41$q;
    reg  br$41$clock;
    reg  [15:0] br$42$d;
    wire  [15:0] br$42$q;
    reg  br$42$clock;
    reg  [15:0] br$43$d;
    wire  [15:0] br$43$q;
    reg  br$43$clock;
    reg  [15:0] br$44$d;
    wire  [15:0] br$44$q;
    reg  br$44$clock;
    reg  [15:0] br$45$d;
    wire  [15:0] br$45$q;
    reg  br$45$clock;
    reg  [15:0] br$46$d;
    wire  [15:0] br$46$q;
    reg  br$46$clock;
    reg  [15:0] br$47$d;
    wire  [15:0] br$47$q;
    reg  br$47$clock;
    reg  [15:0] br$48$d;
    wire  [15:0] br$48$q;
    reg  br$48$clock;
    reg  [15:0] br$49$d;
    wire  [15:0] br$49$q;
    reg  br$49$clock;
    reg  [15:0] br$50$d;
    wire  [15:0] br$50$q;
    reg  br$50$clock;
    reg  [15:0] br$51$d;
    wire  [15:0] br$51$q;
    reg  br$51$clock;
    reg  [15:0] br$52$d;
    wire  [15:0] br$52$q;
    reg  br$52$clock;
    reg  [15:0] br$53$d;
    wire  [15:0] br$53$q;
    reg  br$53$clock;
    reg  [15:0] br$54$d;
    wire  [15:0] br$54$q;
    reg  br$54$clock;
    reg  [15:0] br$55$d;
    wire  [15:0] br$55$q;
    reg  br$55$clock;
    reg  [15:0] br$56$d;
    wire  [15:0] br$56$q;
    reg  br$56$clock;
    reg  [15:0] br$57$d;
    wire  [15:0] br$57$q;
    reg  br$57$clock;
    reg  [15:0] br$58$d;
    wire  [15:0] br$58$q;
    reg  br$58$clock;
    reg  [15:0] br$59$d;
    wire  [15:0] br$59$q;
    reg  br$59$clock;
    reg  [15:0] br$60$d;
    wire  [15:0] br$60$q;
    reg  br$60$clock;
    reg  [15:0] br$61$d;
    wire  [15:0] br$61$q;
    reg  br$61$clock;
    reg  [15:0] br$62$d;
    wire  [15:0] br$62$q;
    reg  br$62$clock;
    reg  [15:0] br$63$d;
    wire  [15:0] br$63$q;
    reg  br$63$clock;
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
    reg  welatch;
    reg  dstart;
    reg  dump;
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
    se$ozr$0 ozr$0(
        .d(ozr$0$d),
        .q(ozr$0$q),
        .clock(ozr$0$clock)
    );
    se$ozr$1 ozr$1(
        .d(ozr$1$d),
        .q(ozr$1$q),
        .clock(ozr$1$clock)
    );
    se$ozr$2 ozr$2(
        .d(ozr$2$d),
        .q(ozr$2$q),
        .clock(ozr$2$clock)
    );
    se$ozr$3 ozr$3(
        .d(ozr$3$d),
        .q(ozr$3$q),
        .clock(ozr$3$clock)
    );
    se$ozr$4 ozr$4(
        .d(ozr$4$d),
        .q(ozr$4$q),
        .clock(ozr$4$clock)
    );
    se$ozr$5 ozr$5(
        .d(ozr$5$d),
        .q(ozr$5$q),
        .clock(ozr$5$clock)
    );
    se$ozr$6 ozr$6(
        .d(ozr$6$d),
        .q(ozr$6$q),
        .clock(ozr$6$clock)
    );
    se$ozr$7 ozr$7(
        .d(ozr$7$d),
        .q(ozr$7$q),
        .clock(ozr$7$clock)
    );
    se$ozr$8 ozr$8(
        .d(ozr$8$d),
        .q(ozr$8$q),
        .clock(ozr$8$clock)
    );
    se$ozr$9 ozr$9(
        .d(ozr$9$d),
        .q(ozr$9$q),
        .clock(ozr$9$clock)
    );
    se$ozr$10 ozr$10(
        .d(ozr$10$d),
        .q(ozr$10$q),
        .clock(ozr$10$clock)
    );
    se$ozr$11 ozr$11(
        .d(ozr$11$d),
        .q(ozr$11$q),
        .clock(ozr$11$clock)
    );
    se$ozr$12 ozr$12(
        .d(ozr$12$d),
        .q(ozr$12$q),
        .clock(ozr$12$clock)
    );
    se$ozr$13 ozr$13(
        .d(ozr$13$d),
        .q(ozr$13$q),
        .clock(ozr$13$clock)
    );
    se$ozr$14 ozr$14(
        .d(ozr$14$d),
        .q(ozr$14$q),
        .clock(ozr$14$clock)
    );
    se$ozr$15 ozr$15(
        .d(ozr$15$d),
        .q(ozr$15$q),
        .clock(ozr$15$clock)
    );
    se$ozr$16 ozr$16(
        .d(ozr$16$d),
        .q(ozr$16$q),
        .clock(ozr$16$clock)
    );
    se$ozr$17 ozr$17(
        .d(ozr$17$d),
        .q(ozr$17$q),
        .clock(ozr$17$clock)
    );
    se$ozr$18 ozr$18(
        .d(ozr$18$d),
        .q(ozr$18$q),
        .clock(ozr$18$clock)
    );
    se$ozr$19 ozr$19(
        .d(ozr$19$d),
        .q(ozr$19$q),
        .clock(ozr$19$clock)
    );
    se$ozr$20 ozr$20(
        .d(ozr$20$d),
        .q(ozr$20$q),
        .clock(ozr$20$clock)
    );
    se$ozr$21 ozr$21(
        .d(ozr$21$d),
        .q(ozr$21$q),
        .clock(ozr$21$clock)
    );
    se$ozr$22 ozr$22(
        .d(ozr$22$d),
        .q(ozr$22$q),
        .clock(ozr$22$clock)
    );
    se$ozr$23 ozr$23(
        .d(ozr$23$d),
        .q(ozr$23$q),
        .clock(ozr$23$clock)
    );
    se$ozr$24 ozr$24(
        .d(ozr$24$d),
        .q(ozr$24$q),
        .clock(ozr$24$clock)
    );
    se$ozr$25 ozr$25(
        .d(ozr$25$d),
        .q(ozr$25$q),
        .clock(ozr$25$clock)
    );
    se$ozr$26 ozr$26(
        .d(ozr$26$d),
        .q(ozr$26$q),
        .clock(ozr$26$clock)
    );
    se$ozr$27 ozr$27(
        .d(ozr$27$d),
        .q(ozr$27$q),
        .clock(ozr$27$clock)
    );
    se$ozr$28 ozr$28(
        .d(ozr$28$d),
        .q(ozr$28$q),
        .clock(ozr$28$clock)
    );
    se$ozr$29 ozr$29(
        .d(ozr$29$d),
        .q(ozr$29$q),
        .clock(ozr$29$clock)
    );
    se$ozr$30 ozr$30(
        .d(ozr$30$d),
        .q(ozr$30$q),
        .clock(ozr$30$clock)
    );
    se$ozr$31 ozr$31(
        .d(ozr$31$d),
        .q(ozr$31$q),
        .clock(ozr$31$clock)
    );
    se$ozr$32 ozr$32(
        .d(ozr$32$d),
        .q(ozr$32$q),
        .clock(ozr$32$clock)
    );
    se$ozr$33 ozr$33(
        .d(ozr$33$d),
        .q(ozr$33$q),
        .clock(ozr$33$clock)
    );
    se$ozr$34 ozr$34(
        .d(ozr$34$d),
        .q(ozr$34$q),
        .clock(ozr$34$clock)
    );
    se$ozr$35 ozr$35(
        .d(ozr$35$d),
        .q(ozr$35$q),
        .clock(ozr$35$clock)
    );
    se$ozr$36 ozr$36(
        .d(ozr$36$d),
        .q(ozr$36$q),
        .clock(ozr$36$clock)
    );
    se$ozr$37 ozr$37(
        .d(ozr$37$d),
        .q(ozr$37$q),
        .clock(ozr$37$clock)
    );
    se$ozr$38 ozr$38(
        .d(ozr$38$d),
        .q(ozr$38$q),
        .clock(ozr$38$clock)
    );
    se$ozr$39 ozr$39(
        .d(ozr$39$d),
        .q(ozr$39$q),
        .clock(ozr$39$clock)
    );
    se$ozr$40 ozr$40(
        .d(ozr$40$d),
        .q(ozr$40$q),
        .clock(ozr$40$clock)
    );
    se$ozr$41 ozr$41(
        .d(ozr$41$d),
        .q(ozr$41$q),
        .clock(ozr$41$clock)
    );
    se$ozr$42 ozr$42(
        .d(ozr$42$d),
        .q(ozr$42$q),
        .clock(ozr$42$clock)
    );
    se$ozr$43 ozr$43(
        .d(ozr$43$d),
        .q(ozr$43$q),
        .clock(ozr$43$clock)
    );
    se$ozr$44 ozr$44(
        .d(ozr$44$d),
        .q(ozr$44$q),
        .clock(ozr$44$clock)
    );
    se$ozr$45 ozr$45(
        .d(ozr$45$d),
        .q(ozr$45$q),
        .clock(ozr$45$clock)
    );
    se$ozr$46 ozr$46(
        .d(ozr$46$d),
        .q(ozr$46$q),
        .clock(ozr$46$clock)
    );
    se$ozr$47 ozr$47(
        .d(ozr$47$d),
        .q(ozr$47$q),
        .clock(ozr$47$clock)
    );
    se$ozr$48 ozr$48(
        .d(ozr$48$d),
        .q(ozr$48$q),
        .clock(ozr$48$clock)
    );
    se$ozr$49 ozr$49(
        .d(ozr$49$d),
        .q(ozr$49$q),
        .clock(ozr$49$clock)
    );
    se$ozr$50 ozr$50(
        .d(ozr$50$d),
        .q(ozr$50$q),
        .clock(ozr$50$clock)
    );
    se$ozr$51 ozr$51(
        .d(ozr$51$d),
        .q(ozr$51$q),
        .clock(ozr$51$clock)
    );
    se$ozr$52 ozr$52(
        .d(ozr$52$d),
        .q(ozr$52$q),
        .clock(ozr$52$clock)
    );
    se$ozr$53 ozr$53(
        .d(ozr$53$d),
        .q(ozr$53$q),
        .clock(ozr$53$clock)
    );
    se$ozr$54 ozr$54(
        .d(ozr$54$d),
        .q(ozr$54$q),
        .clock(ozr$54$clock)
    );
    se$ozr$55 ozr$55(
        .d(ozr$55$d),
        .q(ozr$55$q),
        .clock(ozr$55$clock)
    );
    se$ozr$56 ozr$56(
        .d(ozr$56$d),
        .q(ozr$56$q),
        .clock(ozr$56$clock)
    );
    se$ozr$57 ozr$57(
        .d(ozr$57$d),
        .q(ozr$57$q),
        .clock(ozr$57$clock)
    );
    se$ozr$58 ozr$58(
        .d(ozr$58$d),
        .q(ozr$58$q),
        .clock(ozr$58$clock)
    );
    se$ozr$59 ozr$59(
        .d(ozr$59$d),
        .q(ozr$59$q),
        .clock(ozr$59$clock)
    );
    se$ozr$60 ozr$60(
        .d(ozr$60$d),
        .q(ozr$60$q),
        .clock(ozr$60$clock)
    );
    se$ozr$61 ozr$61(
        .d(ozr$61$d),
        .q(ozr$61$q),
        .clock(ozr$61$clock)
    );
    se$ozr$62 ozr$62(
        .d(ozr$62$d),
        .q(ozr$62$q),
        .clock(ozr$62$clock)
    );
    se$ozr$63 ozr$63(
        .d(ozr$63$d),
        .q(ozr$63$q),
        .clock(ozr$63$clock)
    );
    se$nzr$0 nzr$0(
        .d(nzr$0$d),
        .q(nzr$0$q),
        .clock(nzr$0$clock)
    );
    se$nzr$1 nzr$1(
        .d(nzr$1$d),
        .q(nzr$1$q),
        .clock(nzr$1$clock)
    );
    se$nzr$2 nzr$2(
        .d(nzr$2$d),
        .q(nzr$2$q),
        .clock(nzr$2$clock)
    );
    se$nzr$3 nzr$3(
        .d(nzr$3$d),
        .q(nzr$3$q),
        .clock(nzr$3$clock)
    );
    se$nzr$4 nzr$4(
        .d(nzr$4$d),
        .q(nzr$4$q),
        .clock(nzr$4$clock)
    );
    se$nzr$5 nzr$5(
        .d(nzr$5$d),
        .q(nzr$5$q),
        .clock(nzr$5$clock)
    );
    se$nzr$6 nzr$6(
        .d(nzr$6$d),
        .q(nzr$6$q),
        .clock(nzr$6$clock)
    );
    se$nzr$7 nzr$7(
        .d(nzr$7$d),
        .q(nzr$7$q),
        .clock(nzr$7$clock)
    );
    se$nzr$8 nzr$8(
        .d(nzr$8$d),
        .q(nzr$8$q),
        .clock(nzr$8$clock)
    );
    se$nzr$9 nzr$9(
        .d(nzr$9$d),
        .q(nzr$9$q),
        .clock(nzr$9$clock)
    );
    se$nzr$10 nzr$10(
        .d(nzr$10$d),
        .q(nzr$10$q),
        .clock(nzr$10$clock)
    );
    se$nzr$11 nzr$11(
        .d(nzr$11$d),
        .q(nzr$11$q),
        .clock(nzr$11$clock)
    );
    se$nzr$12 nzr$12(
        .d(nzr$12$d),
        .q(nzr$12$q),
        .clock(nzr$12$clock)
    );
    se$nzr$13 nzr$13(
        .d(nzr$13$d),
        .q(nzr$13$q),
        .clock(nzr$13$clock)
    );
    se$nzr$14 nzr$14(
        .d(nzr$14$d),
        .q(nzr$14$q),
        .clock(nzr$14$clock)
    );
    se$nzr$15 nzr$15(
        .d(nzr$15$d),
        .q(nzr$15$q),
        .clock(nzr$15$clock)
    );
    se$nzr$16 nzr$16(
        .d(nzr$16$d),
        .q(nzr$16$q),
        .clock(nzr$16$clock)
    );
    se$nzr$17 nzr$17(
        .d(nzr$17$d),
        .q(nzr$17$q),
        .clock(nzr$17$clock)
    );
    se$nzr$18 nzr$18(
        .d(nzr$18$d),
        .q(nzr$18$q),
        .clock(nzr$18$clock)
    );
    se$nzr$19 nzr$19(
        .d(nzr$19$d),
        .q(nzr$19$q),
        .clock(nzr$19$clock)
    );
    se$nzr$20 nzr$20(
        .d(nzr$20$d),
        .q(nzr$20$q),
        .clock(nzr$20$clock)
    );
    se$nzr$21 nzr$21(
        .d(nzr$21$d),
        .q(nzr$21$q),
        .clock(nzr$21$clock)
    );
    se$nzr$22 nzr$22(
        .d(nzr$22$d),
        .q(nzr$22$q),
        .clock(nzr$22$clock)
    );
    se$nzr$23 nzr$23(
        .d(nzr$23$d),
        .q(nzr$23$q),
        .clock(nzr$23$clock)
    );
    se$nzr$24 nzr$24(
        .d(nzr$24$d),
        .q(nzr$24$q),
        .clock(nzr$24$clock)
    );
    se$nzr$25 nzr$25(
        .d(nzr$25$d),
        .q(nzr$25$q),
        .clock(nzr$25$clock)
    );
    se$nzr$26 nzr$26(
        .d(nzr$26$d),
        .q(nzr$26$q),
        .clock(nzr$26$clock)
    );
    se$nzr$27 nzr$27(
        .d(nzr$27$d),
        .q(nzr$27$q),
        .clock(nzr$27$clock)
    );
    se$nzr$28 nzr$28(
        .d(nzr$28$d),
        .q(nzr$28$q),
        .clock(nzr$28$clock)
    );
    se$nzr$29 nzr$29(
        .d(nzr$29$d),
        .q(nzr$29$q),
        .clock(nzr$29$clock)
    );
    se$nzr$30 nzr$30(
        .d(nzr$30$d),
        .q(nzr$30$q),
        .clock(nzr$30$clock)
    );
    se$nzr$31 nzr$31(
        .d(nzr$31$d),
        .q(nzr$31$q),
        .clock(nzr$31$clock)
    );
    se$nzr$32 nzr$32(
        .d(nzr$32$d),
        .q(nzr$32$q),
        .clock(nzr$32$clock)
    );
    se$nzr$33 nzr$33(
        .d(nzr$33$d),
        .q(nzr$33$q),
        .clock(nzr$33$clock)
    );
    se$nzr$34 nzr$34(
        .d(nzr$34$d),
        .q(nzr$34$q),
        .clock(nzr$34$clock)
    );
    se$nzr$35 nzr$35(
        .d(nzr$35$d),
        .q(nzr$35$q),
        .clock(nzr$35$clock)
    );
    se$nzr$36 nzr$36(
        .d(nzr$36$d),
        .q(nzr$36$q),
        .clock(nzr$36$clock)
    );
    se$nzr$37 nzr$37(
        .d(nzr$37$d),
        .q(nzr$37$q),
        .clock(nzr$37$clock)
    );
    se$nzr$38 nzr$38(
        .d(nzr$38$d),
        .q(nzr$38$q),
        .clock(nzr$38$clock)
    );
    se$nzr$39 nzr$39(
        .d(nzr$39$d),
        .q(nzr$39$q),
        .clock(nzr$39$clock)
    );
    se$nzr$40 nzr$40(
        .d(nzr$40$d),
        .q(nzr$40$q),
        .clock(nzr$40$clock)
    );
    se$nzr$41 nzr$41(
        .d(nzr$41$d),
        .q(nzr$41$q),
        .clock(nzr$41$clock)
    );
    se$nzr$42 nzr$42(
        .d(nzr$42$d),
        .q(nzr$42$q),
        .clock(nzr$42$clock)
    );
    se$nzr$43 nzr$43(
        .d(nzr$43$d),
        .q(nzr$43$q),
        .clock(nzr$43$clock)
    );
    se$nzr$44 nzr$44(
        .d(nzr$44$d),
        .q(nzr$44$q),
        .clock(nzr$44$clock)
    );
    se$nzr$45 nzr$45(
        .d(nzr$45$d),
        .q(nzr$45$q),
        .clock(nzr$45$clock)
    );
    se$nzr$46 nzr$46(
        .d(nzr$46$d),
        .q(nzr$46$q),
        .clock(nzr$46$clock)
    );
    se$nzr$47 nzr$47(
        .d(nzr$47$d),
        .q(nzr$47$q),
        .clock(nzr$47$clock)
    );
    se$nzr$48 nzr$48(
        .d(nzr$48$d),
        .q(nzr$48$q),
        .clock(nzr$48$clock)
    );
    se$nzr$49 nzr$49(
        .d(nzr$49$d),
        .q(nzr$49$q),
        .clock(nzr$49$clock)
    );
    se$nzr$50 nzr$50(
        .d(nzr$50$d),
        .q(nzr$50$q),
        .clock(nzr$50$clock)
    );
    se$nzr$51 nzr$51(
        .d(nzr$51$d),
        .q(nzr$51$q),
        .clock(nzr$51$clock)
    );
    se$nzr$52 nzr$52(
        .d(nzr$52$d),
        .q(nzr$52$q),
        .clock(nzr$52$clock)
    );
    se$nzr$53 nzr$53(
        .d(nzr$53$d),
        .q(nzr$53$q),
        .clock(nzr$53$clock)
    );
    se$nzr$54 nzr$54(
        .d(nzr$54$d),
        .q(nzr$54$q),
        .clock(nzr$54$clock)
    );
    se$nzr$55 nzr$55(
        .d(nzr$55$d),
        .q(nzr$55$q),
        .clock(nzr$55$clock)
    );
    se$nzr$56 nzr$56(
        .d(nzr$56$d),
        .q(nzr$56$q),
        .clock(nzr$56$clock)
    );
    se$nzr$57 nzr$57(
        .d(nzr$57$d),
        .q(nzr$57$q),
        .clock(nzr$57$clock)
    );
    se$nzr$58 nzr$58(
        .d(nzr$58$d),
        .q(nzr$58$q),
        .clock(nzr$58$clock)
    );
    se$nzr$59 nzr$59(
        .d(nzr$59$d),
        .q(nzr$59$q),
        .clock(nzr$59$clock)
    );
    se$nzr$60 nzr$60(
        .d(nzr$60$d),
        .q(nzr$60$q),
        .clock(nzr$60$clock)
    );
    se$nzr$61 nzr$61(
        .d(nzr$61$d),
        .q(nzr$61$q),
        .clock(nzr$61$clock)
    );
    se$nzr$62 nzr$62(
        .d(nzr$62$d),
        .q(nzr$62$q),
        .clock(nzr$62$clock)
    );
    se$nzr$63 nzr$63(
        .d(nzr$63$d),
        .q(nzr$63$q),
        .clock(nzr$63$clock)
    );
    se$rr$0 rr$0(
        .d(rr$0$d),
        .q(rr$0$q),
        .clock(rr$0$clock)
    );
    se$rr$1 rr$1(
        .d(rr$1$d),
        .q(rr$1$q),
        .clock(rr$1$clock)
    );
    se$rr$2 rr$2(
        .d(rr$2$d),
        .q(rr$2$q),
        .clock(rr$2$clock)
    );
    se$rr$3 rr$3(
        .d(rr$3$d),
        .q(rr$3$q),
        .clock(rr$3$clock)
    );
    se$rr$4 rr$4(
        .d(rr$4$d),
        .q(rr$4$q),
        .clock(rr$4$clock)
    );
    se$rr$5 rr$5(
        .d(rr$5$d),
        .q(rr$5$q),
        .clock(rr$5$clock)
    );
    se$rr$6 rr$6(
        .d(rr$6$d),
        .q(rr$6$q),
        .clock(rr$6$clock)
    );
    se$rr$7 rr$7(
        .d(rr$7$d),
        .q(rr$7$q),
        .clock(rr$7$clock)
    );
    se$rr$8 rr$8(
        .d(rr$8$d),
        .q(rr$8$q),
        .clock(rr$8$clock)
    );
    se$rr$9 rr$9(
        .d(rr$9$d),
        .q(rr$9$q),
        .clock(rr$9$clock)
    );
    se$rr$10 rr$10(
        .d(rr$10$d),
        .q(rr$10$q),
        .clock(rr$10$clock)
    );
    se$rr$11 rr$11(
        .d(rr$11$d),
        .q(rr$11$q),
        .clock(rr$11$clock)
    );
    se$rr$12 rr$12(
        .d(rr$12$d),
        .q(rr$12$q),
        .clock(rr$12$clock)
    );
    se$rr$13 rr$13(
        .d(rr$13$d),
        .q(rr$13$q),
        .clock(rr$13$clock)
    );
    se$rr$14 rr$14(
        .d(rr$14$d),
        .q(rr$14$q),
        .clock(rr$14$clock)
    );
    se$rr$15 rr$15(
        .d(rr$15$d),
        .q(rr$15$q),
        .clock(rr$15$clock)
    );
    se$rr$16 rr$16(
        .d(rr$16$d),
        .q(rr$16$q),
        .clock(rr$16$clock)
    );
    se$rr$17 rr$17(
        .d(rr$17$d),
        .q(rr$17$q),
        .clock(rr$17$clock)
    );
    se$rr$18 rr$18(
        .d(rr$18$d),
        .q(rr$18$q),
        .clock(rr$18$clock)
    );
    se$rr$19 rr$19(
        .d(rr$19$d),
        .q(rr$19$q),
        .clock(rr$19$clock)
    );
    se$rr$20 rr$20(
        .d(rr$20$d),
        .q(rr$20$q),
        .clock(rr$20$clock)
    );
    se$rr$21 rr$21(
        .d(rr$21$d),
        .q(rr$21$q),
        .clock(rr$21$clock)
    );
    se$rr$22 rr$22(
        .d(rr$22$d),
        .q(rr$22$q),
        .clock(rr$22$clock)
    );
    se$rr$23 rr$23(
        .d(rr$23$d),
        .q(rr$23$q),
        .clock(rr$23$clock)
    );
    se$rr$24 rr$24(
        .d(rr$24$d),
        .q(rr$24$q),
        .clock(rr$24$clock)
    );
    se$rr$25 rr$25(
        .d(rr$25$d),
        .q(rr$25$q),
        .clock(rr$25$clock)
    );
    se$rr$26 rr$26(
        .d(rr$26$d),
        .q(rr$26$q),
        .clock(rr$26$clock)
    );
    se$rr$27 rr$27(
        .d(rr$27$d),
        .q(rr$27$q),
        .clock(rr$27$clock)
    );
    se$rr$28 rr$28(
        .d(rr$28$d),
        .q(rr$28$q),
        .clock(rr$28$clock)
    );
    se$rr$29 rr$29(
        .d(rr$29$d),
        .q(rr$29$q),
        .clock(rr$29$clock)
    );
    se$rr$30 rr$30(
        .d(rr$30$d),
        .q(rr$30$q),
        .clock(rr$30$clock)
    );
    se$rr$31 rr$31(
        .d(rr$31$d),
        .q(rr$31$q),
        .clock(rr$31$clock)
    );
    se$rr$32 rr$32(
        .d(rr$32$d),
        .q(rr$32$q),
        .clock(rr$32$clock)
    );
    se$rr$33 rr$33(
        .d(rr$33$d),
        .q(rr$33$q),
        .clock(rr$33$clock)
    );
    se$rr$34 rr$34(
        .d(rr$34$d),
        .q(rr$34$q),
        .clock(rr$34$clock)
    );
    se$rr$35 rr$35(
        .d(rr$35$d),
        .q(rr$35$q),
        .clock(rr$35$clock)
    );
    se$rr$36 rr$36(
        .d(rr$36$d),
        .q(rr$36$q),
        .clock(rr$36$clock)
    );
    se$rr$37 rr$37(
        .d(rr$37$d),
        .q(rr$37$q),
        .clock(rr$37$clock)
    );
    se$rr$38 rr$38(
        .d(rr$38$d),
        .q(rr$38$q),
        .clock(rr$38$clock)
    );
    se$rr$39 rr$39(
        .d(rr$39$d),
        .q(rr$39$q),
        .clock(rr$39$clock)
    );
    se$rr$40 rr$40(
        .d(rr$40$d),
        .q(rr$40$q),
        .clock(rr$40$clock)
    );
    se$rr$41 rr$41(
        .d(rr$41$d),
        .q(rr$41$q),
        .clock(rr$41$clock)
    );
    se$rr$42 rr$42(
        .d(rr$42$d),
        .q(rr$42$q),
        .clock(rr$42$clock)
    );
    se$rr$43 rr$43(
        .d(rr$43$d),
        .q(rr$43$q),
        .clock(rr$43$clock)
    );
    se$rr$44 rr$44(
        .d(rr$44$d),
        .q(rr$44$q),
        .clock(rr$44$clock)
    );
    se$rr$45 rr$45(
        .d(rr$45$d),
        .q(rr$45$q),
        .clock(rr$45$clock)
    );
    se$rr$46 rr$46(
        .d(rr$46$d),
        .q(rr$46$q),
        .clock(rr$46$clock)
    );
    se$rr$47 rr$47(
        .d(rr$47$d),
        .q(rr$47$q),
        .clock(rr$47$clock)
    );
    se$rr$48 rr$48(
        .d(rr$48$d),
        .q(rr$48$q),
        .clock(rr$48$clock)
    );
    se$rr$49 rr$49(
        .d(rr$49$d),
        .q(rr$49$q),
        .clock(rr$49$clock)
    );
    se$rr$50 rr$50(
        .d(rr$50$d),
        .q(rr$50$q),
        .clock(rr$50$clock)
    );
    se$rr$51 rr$51(
        .d(rr$51$d),
        .q(rr$51$q),
        .clock(rr$51$clock)
    );
    se$rr$52 rr$52(
        .d(rr$52$d),
        .q(rr$52$q),
        .clock(rr$52$clock)
    );
    se$rr$53 rr$53(
        .d(rr$53$d),
        .q(rr$53$q),
        .clock(rr$53$clock)
    );
    se$rr$54 rr$54(
        .d(rr$54$d),
        .q(rr$54$q),
        .clock(rr$54$clock)
    );
    se$rr$55 rr$55(
        .d(rr$55$d),
        .q(rr$55$q),
        .clock(rr$55$clock)
    );
    se$rr$56 rr$56(
        .d(rr$56$d),
        .q(rr$56$q),
        .clock(rr$56$clock)
    );
    se$rr$57 rr$57(
        .d(rr$57$d),
        .q(rr$57$q),
        .clock(rr$57$clock)
    );
    se$rr$58 rr$58(
        .d(rr$58$d),
        .q(rr$58$q),
        .clock(rr$58$clock)
    );
    se$rr$59 rr$59(
        .d(rr$59$d),
        .q(rr$59$q),
        .clock(rr$59$clock)
    );
    se$rr$60 rr$60(
        .d(rr$60$d),
        .q(rr$60$q),
        .clock(rr$60$clock)
    );
    se$rr$61 rr$61(
        .d(rr$61$d),
        .q(rr$61$q),
        .clock(rr$61$clock)
    );
    se$rr$62 rr$62(
        .d(rr$62$d),
        .q(rr$62$q),
        .clock(rr$62$clock)
    );
    se$rr$63 rr$63(
        .d(rr$63$d),
        .q(rr$63$q),
        .clock(rr$63$clock)
    );
    se$gr$0 gr$0(
        .d(gr$0$d),
        .q(gr$0$q),
        .clock(gr$0$clock)
    );
    se$gr$1 gr$1(
        .d(gr$1$d),
        .q(gr$1$q),
        .clock(gr$1$clock)
    );
    se$gr$2 gr$2(
        .d(gr$2$d),
        .q(gr$2$q),
        .clock(gr$2$clock)
    );
    se$gr$3 gr$3(
        .d(gr$3$d),
        .q(gr$3$q),
        .clock(gr$3$clock)
    );
    se$gr$4 gr$4(
        .d(gr$4$d),
        .q(gr$4$q),
        .clock(gr$4$clock)
    );
    se$gr$5 gr$5(
        .d(gr$5$d),
        .q(gr$5$q),
        .clock(gr$5$clock)
    );
    se$gr$6 gr$6(
        .d(gr$6$d),
        .q(gr$6$q),
        .clock(gr$6$clock)
    );
    se$gr$7 gr$7(
        .d(gr$7$d),
        .q(gr$7$q),
        .clock(gr$7$clock)
    );
    se$gr$8 gr$8(
        .d(gr$8$d),
        .q(gr$8$q),
        .clock(gr$8$clock)
    );
    se$gr$9 gr$9(
        .d(gr$9$d),
        .q(gr$9$q),
        .clock(gr$9$clock)
    );
    se$gr$10 gr$10(
        .d(gr$10$d),
        .q(gr$10$q),
        .clock(gr$10$clock)
    );
    se$gr$11 gr$11(
        .d(gr$11$d),
        .q(gr$11$q),
        .clock(gr$11$clock)
    );
    se$gr$12 gr$12(
        .d(gr$12$d),
        .q(gr$12$q),
        .clock(gr$12$clock)
    );
    se$gr$13 gr$13(
        .d(gr$13$d),
        .q(gr$13$q),
        .clock(gr$13$clock)
    );
    se$gr$14 gr$14(
        .d(gr$14$d),
        .q(gr$14$q),
        .clock(gr$14$clock)
    );
    se$gr$15 gr$15(
        .d(gr$15$d),
        .q(gr$15$q),
        .clock(gr$15$clock)
    );
    se$gr$16 gr$16(
        .d(gr$16$d),
        .q(gr$16$q),
        .clock(gr$16$clock)
    );
    se$gr$17 gr$17(
        .d(gr$17$d),
        .q(gr$17$q),
        .clock(gr$17$clock)
    );
    se$gr$18 gr$18(
        .d(gr$18$d),
        .q(gr$18$q),
        .clock(gr$18$clock)
    );
    se$gr$19 gr$19(
        .d(gr$19$d),
        .q(gr$19$q),
        .clock(gr$19$clock)
    );
    se$gr$20 gr$20(
        .d(gr$20$d),
        .q(gr$20$q),
        .clock(gr$20$clock)
    );
    se$gr$21 gr$21(
        .d(gr$21$d),
        .q(gr$21$q),
        .clock(gr$21$clock)
    );
    se$gr$22 gr$22(
        .d(gr$22$d),
        .q(gr$22$q),
        .clock(gr$22$clock)
    );
    se$gr$23 gr$23(
        .d(gr$23$d),
        .q(gr$23$q),
        .clock(gr$23$clock)
    );
    se$gr$24 gr$24(
        .d(gr$24$d),
        .q(gr$24$q),
        .clock(gr$24$clock)
    );
    se$gr$25 gr$25(
        .d(gr$25$d),
        .q(gr$25$q),
        .clock(gr$25$clock)
    );
    se$gr$26 gr$26(
        .d(gr$26$d),
        .q(gr$26$q),
        .clock(gr$26$clock)
    );
    se$gr$27 gr$27(
        .d(gr$27$d),
        .q(gr$27$q),
        .clock(gr$27$clock)
    );
    se$gr$28 gr$28(
        .d(gr$28$d),
        .q(gr$28$q),
        .clock(gr$28$clock)
    );
    se$gr$29 gr$29(
        .d(gr$29$d),
        .q(gr$29$q),
        .clock(gr$29$clock)
    );
    se$gr$30 gr$30(
        .d(gr$30$d),
        .q(gr$30$q),
        .clock(gr$30$clock)
    );
    se$gr$31 gr$31(
        .d(gr$31$d),
        .q(gr$31$q),
        .clock(gr$31$clock)
    );
    se$gr$32 gr$32(
        .d(gr$32$d),
        .q(gr$32$q),
        .clock(gr$32$clock)
    );
    se$gr$33 gr$33(
        .d(gr$33$d),
        .q(gr$33$q),
        .clock(gr$33$clock)
    );
    se$gr$34 gr$34(
        .d(gr$34$d),
        .q(gr$34$q),
        .clock(gr$34$clock)
    );
    se$gr$35 gr$35(
        .d(gr$35$d),
        .q(gr$35$q),
        .clock(gr$35$clock)
    );
    se$gr$36 gr$36(
        .d(gr$36$d),
        .q(gr$36$q),
        .clock(gr$36$clock)
    );
    se$gr$37 gr$37(
        .d(gr$37$d),
        .q(gr$37$q),
        .clock(gr$37$clock)
    );
    se$gr$38 gr$38(
        .d(gr$38$d),
        .q(gr$38$q),
        .clock(gr$38$clock)
    );
    se$gr$39 gr$39(
        .d(gr$39$d),
        .q(gr$39$q),
        .clock(gr$39$clock)
    );
    se$gr$40 gr$40(
        .d(gr$40$d),
        .q(gr$40$q),
        .clock(gr$40$clock)
    );
    se$gr$41 gr$41(
        .d(gr$41$d),
        .q(gr$41$q),
        .clock(gr$41$clock)
    );
    se$gr$42 gr$42(
        .d(gr$42$d),
        .q(gr$42$q),
        .clock(gr$42$clock)
    );
    se$gr$43 gr$43(
        .d(gr$43$d),
        .q(gr$43$q),
        .clock(gr$43$clock)
    );
    se$gr$44 gr$44(
        .d(gr$44$d),
        .q(gr$44$q),
        .clock(gr$44$clock)
    );
    se$gr$45 gr$45(
        .d(gr$45$d),
        .q(gr$45$q),
        .clock(gr$45$clock)
    );
    se$gr$46 gr$46(
        .d(gr$46$d),
        .q(gr$46$q),
        .clock(gr$46$clock)
    );
    se$gr$47 gr$47(
        .d(gr$47$d),
        .q(gr$47$q),
        .clock(gr$47$clock)
    );
    se$gr$48 gr$48(
        .d(gr$48$d),
        .q(gr$48$q),
        .clock(gr$48$clock)
    );
    se$gr$49 gr$49(
        .d(gr$49$d),
        .q(gr$49$q),
        .clock(gr$49$clock)
    );
    se$gr$50 gr$50(
        .d(gr$50$d),
        .q(gr$50$q),
        .clock(gr$50$clock)
    );
    se$gr$51 gr$51(
        .d(gr$51$d),
        .q(gr$51$q),
        .clock(gr$51$clock)
    );
    se$gr$52 gr$52(
        .d(gr$52$d),
        .q(gr$52$q),
        .clock(gr$52$clock)
    );
    se$gr$53 gr$53(
        .d(gr$53$d),
        .q(gr$53$q),
        .clock(gr$53$clock)
    );
    se$gr$54 gr$54(
        .d(gr$54$d),
        .q(gr$54$q),
        .clock(gr$54$clock)
    );
    se$gr$55 gr$55(
        .d(gr$55$d),
        .q(gr$55$q),
        .clock(gr$55$clock)
    );
    se$gr$56 gr$56(
        .d(gr$56$d),
        .q(gr$56$q),
        .clock(gr$56$clock)
    );
    se$gr$57 gr$57(
        .d(gr$57$d),
        .q(gr$57$q),
        .clock(gr$57$clock)
    );
    se$gr$58 gr$58(
        .d(gr$58$d),
        .q(gr$58$q),
        .clock(gr$58$clock)
    );
    se$gr$59 gr$59(
        .d(gr$59$d),
        .q(gr$59$q),
        .clock(gr$59$clock)
    );
    se$gr$60 gr$60(
        .d(gr$60$d),
        .q(gr$60$q),
        .clock(gr$60$clock)
    );
    se$gr$61 gr$61(
        .d(gr$61$d),
        .q(gr$61$q),
        .clock(gr$61$clock)
    );
    se$gr$62 gr$62(
        .d(gr$62$d),
        .q(gr$62$q),
        .clock(gr$62$clock)
    );
    se$gr$63 gr$63(
        .d(gr$63$d),
        .q(gr$63$q),
        .clock(gr$63$clock)
    );
    se$br$0 br$0(
        .d(br$0$d),
        .q(br$0$q),
        .clock(br$0$clock)
    );
    se$br$1 br$1(
        .d(br$1$d),
        .q(br$1$q),
        .clock(br$1$clock)
    );
    se$br$2 br$2(
        .d(br$2$d),
        .q(br$2$q),
        .clock(br$2$clock)
    );
    se$br$3 br$3(
        .d(br$3$d),
        .q(br$3$q),
        .clock(br$3$clock)
    );
    se$br$4 br$4(
        .d(br$4$d),
        .q(br$4$q),
        .clock(br$4$clock)
    );
    se$br$5 br$5(
        .d(br$5$d),
        .q(br$5$q),
        .clock(br$5$clock)
    );
    se$br$6 br$6(
        .d(br$6$d),
        .q(br$6$q),
        .clock(br$6$clock)
    );
    se$br$7 br$7(
        .d(br$7$d),
        .q(br$7$q),
        .clock(br$7$clock)
    );
    se$br$8 br$8(
        .d(br$8$d),
        .q(br$8$q),
        .clock(br$8$clock)
    );
    se$br$9 br$9(
        .d(br$9$d),
        .q(br$9$q),
        .clock(br$9$clock)
    );
    se$br$10 br$10(
        .d(br$10$d),
        .q(br$10$q),
        .clock(br$10$clock)
    );
    se$br$11 br$11(
        .d(br$11$d),
        .q(br$11$q),
        .clock(br$11$clock)
    );
    se$br$12 br$12(
        .d(br$12$d),
        .q(br$12$q),
        .clock(br$12$clock)
    );
    se$br$13 br$13(
        .d(br$13$d),
        .q(br$13$q),
        .clock(br$13$clock)
    );
    se$br$14 br$14(
        .d(br$14$d),
        .q(br$14$q),
        .clock(br$14$clock)
    );
    se$br$15 br$15(
        .d(br$15$d),
        .q(br$15$q),
        .clock(br$15$clock)
    );
    se$br$16 br$16(
        .d(br$16$d),
        .q(br$16$q),
        .clock(br$16$clock)
    );
    se$br$17 br$17(
        .d(br$17$d),
        .q(br$17$q),
        .clock(br$17$clock)
    );
    se$br$18 br$18(
        .d(br$18$d),
        .q(br$18$q),
        .clock(br$18$clock)
    );
    se$br$19 br$19(
        .d(br$19$d),
        .q(br$19$q),
        .clock(br$19$clock)
    );
    se$br$20 br$20(
        .d(br$20$d),
        .q(br$20$q),
        .clock(br$20$clock)
    );
    se$br$21 br$21(
        .d(br$21$d),
        .q(br$21$q),
        .clock(br$21$clock)
    );
    se$br$22 br$22(
        .d(br$22$d),
        .q(br$22$q),
        .clock(br$22$clock)
    );
    se$br$23 br$23(
        .d(br$23$d),
        .q(br$23$q),
        .clock(br$23$clock)
    );
    se$br$24 br$24(
        .d(br$24$d),
        .q(br$24$q),
        .clock(br$24$clock)
    );
    se$br$25 br$25(
        .d(br$25$d),
        .q(br$25$q),
        .clock(br$25$clock)
    );
    se$br$26 br$26(
        .d(br$26$d),
        .q(br$26$q),
        .clock(br$26$clock)
    );
    se$br$27 br$27(
        .d(br$27$d),
        .q(br$27$q),
        .clock(br$27$clock)
    );
    se$br$28 br$28(
        .d(br$28$d),
        .q(br$28$q),
        .clock(br$28$clock)
    );
    se$br$29 br$29(
        .d(br$29$d),
        .q(br$29$q),
        .clock(br$29$clock)
    );
    se$br$30 br$30(
        .d(br$30$d),
        .q(br$30$q),
        .clock(br$30$clock)
    );
    se$br$31 br$31(
        .d(br$31$d),
        .q(br$31$q),
        .clock(br$31$clock)
    );
    se$br$32 br$32(
        .d(br$32$d),
        .q(br$32$q),
        .clock(br$32$clock)
    );
    se$br$33 br$33(
        .d(br$33$d),
        .q(br$33$q),
        .clock(br$33$clock)
    );
    se$br$34 br$34(
        .d(br$34$d),
        .q(br$34$q),
        .clock(br$34$clock)
    );
    se$br$35 br$35(
        .d(br$35$d),
        .q(br$35$q),
        .clock(br$35$clock)
    );
    se$br$36 br$36(
        .d(br$36$d),
        .q(br$36$q),
        .clock(br$36$clock)
    );
    se$br$37 br$37(
        .d(br$37$d),
        .q(br$37$q),
        .clock(br$37$clock)
    );
    se$br$38 br$38(
        .d(br$38$d),
        .q(br$38$q),
        .clock(br$38$clock)
    );
    se$br$39 br$39(
        .d(br$39$d),
        .q(br$39$q),
        .clock(br$39$clock)
    );
    se$br$40 br$40(
        .d(br$40$d),
        .q(br$40$q),
        .clock(br$40$clock)
    );
    se$br$41 br$41(
        .d(br$41$d),
        .q(br$41$q),
        .clock(br$41$clock)
    );
    se$br$42 br$42(
        .d(br$42$d),
        .q(br$42$q),
        .clock(br$42$clock)
    );
    se$br$43 br$43(
        .d(br$43$d),
        .q(br$43$q),
        .clock(br$43$clock)
    );
    se$br$44 br$44(
        .d(br$44$d),
        .q(br$44$q),
        .clock(br$44$clock)
    );
    se$br$45 br$45(
        .d(br$45$d),
        .q(br$45$q),
        .clock(br$45$clock)
    );
    se$br$46 br$46(
        .d(br$46$d),
        .q(br$46$q),
        .clock(br$46$clock)
    );
    se$br$47 br$47(
        .d(br$47$d),
        .q(br$47$q),
        .clock(br$47$clock)
    );
    se$br$48 br$48(
        .d(br$48$d),
        .q(br$48$q),
        .clock(br$48$clock)
    );
    se$br$49 br$49(
        .d(br$49$d),
        .q(br$49$q),
        .clock(br$49$clock)
    );
    se$br$50 br$50(
        .d(br$50$d),
        .q(br$50$q),
        .clock(br$50$clock)
    );
    se$br$51 br$51(
        .d(br$51$d),
        .q(br$51$q),
        .clock(br$51$clock)
    );
    se$br$52 br$52(
        .d(br$52$d),
        .q(br$52$q),
        .clock(br$52$clock)
    );
    se$br$53 br$53(
        .d(br$53$d),
        .q(br$53$q),
        .clock(br$53$clock)
    );
    se$br$54 br$54(
        .d(br$54$d),
        .q(br$54$q),
        .clock(br$54$clock)
    );
    se$br$55 br$55(
        .d(br$55$d),
        .q(br$55$q),
        .clock(br$55$clock)
    );
    se$br$56 br$56(
        .d(br$56$d),
        .q(br$56$q),
        .clock(br$56$clock)
    );
    se$br$57 br$57(
        .d(br$57$d),
        .q(br$57$q),
        .clock(br$57$clock)
    );
    se$br$58 br$58(
        .d(br$58$d),
        .q(br$58$q),
        .clock(br$58$clock)
    );
    se$br$59 br$59(
        .d(br$59$d),
        .q(br$59$q),
        .clock(br$59$clock)
    );
    se$br$60 br$60(
        .d(br$60$d),
        .q(br$60$q),
        .clock(br$60$clock)
    );
    se$br$61 br$61(
        .d(br$61$d),
        .q(br$61$q),
        .clock(br$61$clock)
    );
    se$br$62 br$62(
        .d(br$62$d),
        .q(br$62$q),
        .clock(br$62$clock)
    );
    se$br$63 br$63(
        .d(br$63$d),
        .q(br$63$q),
        .clock(br$63$clock)
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
        zc$0$clock = clock;
        ozr$0$clock = clock;
        nzr$0$clock = clock;
        rr$0$clock = clock;
        gr$0$clock = clock;
        br$0$clock = clock;
        wes$0$clock = clock;
        ozr$0$d = ozr$0$q;
        nzr$0$d = nzr$0$q;
        rr$0$d = rr$0$q;
        gr$0$d = gr$0$q;
        br$0$d = br$0$q;
        wes$0$d = wes$0$q;
        zc$1$clock = clock;
        ozr$1$clock = clock;
        nzr$1$clock = clock;
        rr$1$clock = clock;
        gr$1$clock = clock;
        br$1$clock = clock;
        wes$1$clock = clock;
        ozr$1$d = ozr$1$q;
        nzr$1$d = nzr$1$q;
        rr$1$d = rr$1$q;
        gr$1$d = gr$1$q;
        br$1$d = br$1$q;
        wes$1$d = wes$1$q;
        zc$2$clock = clock;
        ozr$2$clock = clock;
        nzr$2$clock = clock;
        rr$2$clock = clock;
        gr$2$clock = clock;
        br$2$clock = clock;
        wes$2$clock = clock;
        ozr$2$d = ozr$2$q;
        nzr$2$d = nzr$2$q;
        rr$2$d = rr$2$q;
        gr$2$d = gr$2$q;
        br$2$d = br$2$q;
        wes$2$d = wes$2$q;
        zc$3$clock = clock;
        ozr$3$clock = clock;
        nzr$3$clock = clock;
        rr$3$clock = clock;
        gr$3$clock = clock;
        br$3$clock = clock;
        wes$3$clock = clock;
        ozr$3$d = ozr$3$q;
        nzr$3$d = nzr$3$q;
        rr$3$d = rr$3$q;
        gr$3$d = gr$3$q;
        br$3$d = br$3$q;
        wes$3$d = wes$3$q;
        zc$4$clock = clock;
        ozr$4$clock = clock;
        nzr$4$clock = clock;
        rr$4$clock = clock;
        gr$4$clock = clock;
        br$4$clock = clock;
        wes$4$clock = clock;
        ozr$4$d = ozr$4$q;
        nzr$4$d = nzr$4$q;
        rr$4$d = rr$4$q;
        gr$4$d = gr$4$q;
        br$4$d = br$4$q;
        wes$4$d = wes$4$q;
        zc$5$clock = clock;
        ozr$5$clock = clock;
        nzr$5$clock = clock;
        rr$5$clock = clock;
        gr$5$clock = clock;
        br$5$clock = clock;
        wes$5$clock = clock;
        ozr$5$d = ozr$5$q;
        nzr$5$d = nzr$5$q;
        rr$5$d = rr$5$q;
        gr$5$d = gr$5$q;
        br$5$d = br$5$q;
        wes$5$d = wes$5$q;
        zc$6$clock = clock;
        ozr$6$clock = clock;
        nzr$6$clock = clock;
        rr$6$clock = clock;
        gr$6$clock = clock;
        br$6$clock = clock;
        wes$6$clock = clock;
        ozr$6$d = ozr$6$q;
        nzr$6$d = nzr$6$q;
        rr$6$d = rr$6$q;
        gr$6$d = gr$6$q;
        br$6$d = br$6$q;
        wes$6$d = wes$6$q;
        zc$7$clock = clock;
        ozr$7$clock = clock;
        nzr$7$clock = clock;
        rr$7$clock = clock;
        gr$7$clock = clock;
        br$7$clock = clock;
        wes$7$clock = clock;
        ozr$7$d = ozr$7$q;
        nzr$7$d = nzr$7$q;
        rr$7$d = rr$7$q;
        gr$7$d = gr$7$q;
        br$7$d = br$7$q;
        wes$7$d = wes$7$q;
        zc$8$clock = clock;
        ozr$8$clock = clock;
        nzr$8$clock = clock;
        rr$8$clock = clock;
        gr$8$clock = clock;
        br$8$clock = clock;
        wes$8$clock = clock;
        ozr$8$d = ozr$8$q;
        nzr$8$d = nzr$8$q;
        rr$8$d = rr$8$q;
        gr$8$d = gr$8$q;
        br$8$d = br$8$q;
        wes$8$d = wes$8$q;
        zc$9$clock = clock;
        ozr$9$clock = clock;
        nzr$9$clock = clock;
        rr$9$clock = clock;
        gr$9$clock = clock;
        br$9$clock = clock;
        wes$9$clock = clock;
        ozr$9$d = ozr$9$q;
        nzr$9$d = nzr$9$q;
        rr$9$d = rr$9$q;
        gr$9$d = gr$9$q;
        br$9$d = br$9$q;
        wes$9$d = wes$9$q;
        zc$10$clock = clock;
        ozr$10$clock = clock;
        nzr$10$clock = clock;
        rr$10$clock = clock;
        gr$10$clock = clock;
        br$10$clock = clock;
        wes$10$clock = clock;
        ozr$10$d = ozr$10$q;
        nzr$10$d = nzr$10$q;
        rr$10$d = rr$10$q;
        gr$10$d = gr$10$q;
        br$10$d = br$10$q;
        wes$10$d = wes$10$q;
        zc$11$clock = clock;
        ozr$11$clock = clock;
        nzr$11$clock = clock;
        rr$11$clock = clock;
        gr$11$clock = clock;
        br$11$clock = clock;
        wes$11$clock = clock;
        ozr$11$d = ozr$11$q;
        nzr$11$d = nzr$11$q;
        rr$11$d = rr$11$q;
        gr$11$d = gr$11$q;
        br$11$d = br$11$q;
        wes$11$d = wes$11$q;
        zc$12$clock = clock;
        ozr$12$clock = clock;
        nzr$12$clock = clock;
        rr$12$clock = clock;
        gr$12$clock = clock;
        br$12$clock = clock;
        wes$12$clock = clock;
        ozr$12$d = ozr$12$q;
        nzr$12$d = nzr$12$q;
        rr$12$d = rr$12$q;
        gr$12$d = gr$12$q;
        br$12$d = br$12$q;
        wes$12$d = wes$12$q;
        zc$13$clock = clock;
        ozr$13$clock = clock;
        nzr$13$clock = clock;
        rr$13$clock = clock;
        gr$13$clock = clock;
        br$13$clock = clock;
        wes$13$clock = clock;
        ozr$13$d = ozr$13$q;
        nzr$13$d = nzr$13$q;
        rr$13$d = rr$13$q;
        gr$13$d = gr$13$q;
        br$13$d = br$13$q;
        wes$13$d = wes$13$q;
        zc$14$clock = clock;
        ozr$14$clock = clock;
        nzr$14$clock = clock;
        rr$14$clock = clock;
        gr$14$clock = clock;
        br$14$clock = clock;
        wes$14$clock = clock;
        ozr$14$d = ozr$14$q;
        nzr$14$d = nzr$14$q;
        rr$14$d = rr$14$q;
        gr$14$d = gr$14$q;
        br$14$d = br$14$q;
        wes$14$d = wes$14$q;
        zc$15$clock = clock;
        ozr$15$clock = clock;
        nzr$15$clock = clock;
        rr$15$clock = clock;
        gr$15$clock = clock;
        br$15$clock = clock;
        wes$15$clock = clock;
        ozr$15$d = ozr$15$q;
        nzr$15$d = nzr$15$q;
        rr$15$d = rr$15$q;
        gr$15$d = gr$15$q;
        br$15$d = br$15$q;
        wes$15$d = wes$15$q;
        zc$16$clock = clock;
        ozr$16$clock = clock;
        nzr$16$clock = clock;
        rr$16$clock = clock;
        gr$16$clock = clock;
        br$16$clock = clock;
        wes$16$clock = clock;
        ozr$16$d = ozr$16$q;
        nzr$16$d = nzr$16$q;
        rr$16$d = rr$16$q;
        gr$16$d = gr$16$q;
        br$16$d = br$16$q;
        wes$16$d = wes$16$q;
        zc$17$clock = clock;
        ozr$17$clock = clock;
        nzr$17$clock = clock;
        rr$17$clock = clock;
        gr$17$clock = clock;
        br$17$clock = clock;
        wes$17$clock = clock;
        ozr$17$d = ozr$17$q;
        nzr$17$d = nzr$17$q;
        rr$17$d = rr$17$q;
        gr$17$d = gr$17$q;
        br$17$d = br$17$q;
        wes$17$d = wes$17$q;
        zc$18$clock = clock;
        ozr$18$clock = clock;
        nzr$18$clock = clock;
        rr$18$clock = clock;
        gr$18$clock = clock;
        br$18$clock = clock;
        wes$18$clock = clock;
        ozr$18$d = ozr$18$q;
        nzr$18$d = nzr$18$q;
        rr$18$d = rr$18$q;
        gr$18$d = gr$18$q;
        br$18$d = br$18$q;
        wes$18$d = wes$18$q;
        zc$19$clock = clock;
        ozr$19$clock = clock;
        nzr$19$clock = clock;
        rr$19$clock = clock;
        gr$19$clock = clock;
        br$19$clock = clock;
        wes$19$clock = clock;
        ozr$19$d = ozr$19$q;
        nzr$19$d = nzr$19$q;
        rr$19$d = rr$19$q;
        gr$19$d = gr$19$q;
        br$19$d = br$19$q;
        wes$19$d = wes$19$q;
        zc$20$clock = clock;
        ozr$20$clock = clock;
        nzr$20$clock = clock;
        rr$20$clock = clock;
        gr$20$clock = clock;
        br$20$clock = clock;
        wes$20$clock = clock;
        ozr$20$d = ozr$20$q;
        nzr$20$d = nzr$20$q;
        rr$20$d = rr$20$q;
        gr$20$d = gr$20$q;
        br$20$d = br$20$q;
        wes$20$d = wes$20$q;
        zc$21$clock = clock;
        ozr$21$clock = clock;
        nzr$21$clock = clock;
        rr$21$clock = clock;
        gr$21$clock = clock;
        br$21$clock = clock;
        wes$21$clock = clock;
        ozr$21$d = ozr$21$q;
        nzr$21$d = nzr$21$q;
        rr$21$d = rr$21$q;
        gr$21$d = gr$21$q;
        br$21$d = br$21$q;
        wes$21$d = wes$21$q;
        zc$22$clock = clock;
        ozr$22$clock = clock;
        nzr$22$clock = clock;
        rr$22$clock = clock;
        gr$22$clock = clock;
        br$22$clock = clock;
        wes$22$clock = clock;
        ozr$22$d = ozr$22$q;
        nzr$22$d = nzr$22$q;
        rr$22$d = rr$22$q;
        gr$22$d = gr$22$q;
        br$22$d = br$22$q;
        wes$22$d = wes$22$q;
        zc$23$clock = clock;
        ozr$23$clock = clock;
        nzr$23$clock = clock;
        rr$23$clock = clock;
        gr$23$clock = clock;
        br$23$clock = clock;
        wes$23$clock = clock;
        ozr$23$d = ozr$23$q;
        nzr$23$d = nzr$23$q;
        rr$23$d = rr$23$q;
        gr$23$d = gr$23$q;
        br$23$d = br$23$q;
        wes$23$d = wes$23$q;
        zc$24$clock = clock;
        ozr$24$clock = clock;
        nzr$24$clock = clock;
        rr$24$clock = clock;
        gr$24$clock = clock;
        br$24$clock = clock;
        wes$24$clock = clock;
        ozr$24$d = ozr$24$q;
        nzr$24$d = nzr$24$q;
        rr$24$d = rr$24$q;
        gr$24$d = gr$24$q;
        br$24$d = br$24$q;
        wes$24$d = wes$24$q;
        zc$25$clock = clock;
        ozr$25$clock = clock;
        nzr$25$clock = clock;
        rr$25$clock = clock;
        gr$25$clock = clock;
        br$25$clock = clock;
        wes$25$clock = clock;
        ozr$25$d = ozr$25$q;
        nzr$25$d = nzr$25$q;
        rr$25$d = rr$25$q;
        gr$25$d = gr$25$q;
        br$25$d = br$25$q;
        wes$25$d = wes$25$q;
        zc$26$clock = clock;
        ozr$26$clock = clock;
        nzr$26$clock = clock;
        rr$26$clock = clock;
        gr$26$clock = clock;
        br$26$clock = clock;
        wes$26$clock = clock;
        ozr$26$d = ozr$26$q;
        nzr$26$d = nzr$26$q;
        rr$26$d = rr$26$q;
        gr$26$d = gr$26$q;
        br$26$d = br$26$q;
        wes$26$d = wes$26$q;
        zc$27$clock = clock;
        ozr$27$clock = clock;
        nzr$27$clock = clock;
        rr$27$clock = clock;
        gr$27$clock = clock;
        br$27$clock = clock;
        wes$27$clock = clock;
        ozr$27$d = ozr$27$q;
        nzr$27$d = nzr$27$q;
        rr$27$d = rr$27$q;
        gr$27$d = gr$27$q;
        br$27$d = br$27$q;
        wes$27$d = wes$27$q;
        zc$28$clock = clock;
        ozr$28$clock = clock;
        nzr$28$clock = clock;
        rr$28$clock = clock;
        gr$28$clock = clock;
        br$28$clock = clock;
        wes$28$clock = clock;
        ozr$28$d = ozr$28$q;
        nzr$28$d = nzr$28$q;
        rr$28$d = rr$28$q;
        gr$28$d = gr$28$q;
        br$28$d = br$28$q;
        wes$28$d = wes$28$q;
        zc$29$clock = clock;
        ozr$29$clock = clock;
        nzr$29$clock = clock;
        rr$29$clock = clock;
        gr$29$clock = clock;
        br$29$clock = clock;
        wes$29$clock = clock;
        ozr$29$d = ozr$29$q;
        nzr$29$d = nzr$29$q;
        rr$29$d = rr$29$q;
        gr$29$d = gr$29$q;
        br$29$d = br$29$q;
        wes$29$d = wes$29$q;
        zc$30$clock = clock;
        ozr$30$clock = clock;
        nzr$30$clock = clock;
        rr$30$clock = clock;
        gr$30$clock = clock;
        br$30$clock = clock;
        wes$30$clock = clock;
        ozr$30$d = ozr$30$q;
        nzr$30$d = nzr$30$q;
        rr$30$d = rr$30$q;
        gr$30$d = gr$30$q;
        br$30$d = br$30$q;
        wes$30$d = wes$30$q;
        zc$31$clock = clock;
        ozr$31$clock = clock;
        nzr$31$clock = clock;
        rr$31$clock = clock;
        gr$31$clock = clock;
        br$31$clock = clock;
        wes$31$clock = clock;
        ozr$31$d = ozr$31$q;
        nzr$31$d = nzr$31$q;
        rr$31$d = rr$31$q;
        gr$31$d = gr$31$q;
        br$31$d = br$31$q;
        wes$31$d = wes$31$q;
        zc$32$clock = clock;
        ozr$32$clock = clock;
        nzr$32$clock = clock;
        rr$32$clock = clock;
        gr$32$clock = clock;
        br$32$clock = clock;
        wes$32$clock = clock;
        ozr$32$d = ozr$32$q;
        nzr$32$d = nzr$32$q;
        rr$32$d = rr$32$q;
        gr$32$d = gr$32$q;
        br$32$d = br$32$q;
        wes$32$d = wes$32$q;
        zc$33$clock = clock;
        ozr$33$clock = clock;
        nzr$33$clock = clock;
        rr$33$clock = clock;
        gr$33$clock = clock;
        br$33$clock = clock;
        wes$33$clock = clock;
        ozr$33$d = ozr$33$q;
        nzr$33$d = nzr$33$q;
        rr$33$d = rr$33$q;
        gr$33$d = gr$33$q;
        br$33$d = br$33$q;
        wes$33$d = wes$33$q;
        zc$34$clock = clock;
        ozr$34$clock = clock;
        nzr$34$clock = clock;
        rr$34$clock = clock;
        gr$34$clock = clock;
        br$34$clock = clock;
        wes$34$clock = clock;
        ozr$34$d = ozr$34$q;
        nzr$34$d = nzr$34$q;
        rr$34$d = rr$34$q;
        gr$34$d = gr$34$q;
        br$34$d = br$34$q;
        wes$34$d = wes$34$q;
        zc$35$clock = clock;
        ozr$35$clock = clock;
        nzr$35$clock = clock;
        rr$35$clock = clock;
        gr$35$clock = clock;
        br$35$clock = clock;
        wes$35$clock = clock;
        ozr$35$d = ozr$35$q;
        nzr$35$d = nzr$35$q;
        rr$35$d = rr$35$q;
        gr$35$d = gr$35$q;
        br$35$d = br$35$q;
        wes$35$d = wes$35$q;
        zc$36$clock = clock;
        ozr$36$clock = clock;
        nzr$36$clock = clock;
        rr$36$clock = clock;
        gr$36$clock = clock;
        br$36$clock = clock;
        wes$36$clock = clock;
        ozr$36$d = ozr$36$q;
        nzr$36$d = nzr$36$q;
        rr$36$d = rr$36$q;
        gr$36$d = gr$36$q;
        br$36$d = br$36$q;
        wes$36$d = wes$36$q;
        zc$37$clock = clock;
        ozr$37$clock = clock;
        nzr$37$clock = clock;
        rr$37$clock = clock;
        gr$37$clock = clock;
        br$37$clock = clock;
        wes$37$clock = clock;
        ozr$37$d = ozr$37$q;
        nzr$37$d = nzr$37$q;
        rr$37$d = rr$37$q;
        gr$37$d = gr$37$q;
        br$37$d = br$37$q;
        wes$37$d = wes$37$q;
        zc$38$clock = clock;
        ozr$38$clock = clock;
        nzr$38$clock = clock;
        rr$38$clock = clock;
        gr$38$clock = clock;
        br$38$clock = clock;
        wes$38$clock = clock;
        ozr$38$d = ozr$38$q;
        nzr$38$d = nzr$38$q;
        rr$38$d = rr$38$q;
        gr$38$d = gr$38$q;
        br$38$d = br$38$q;
        wes$38$d = wes$38$q;
        zc$39$clock = clock;
        ozr$39$clock = clock;
        nzr$39$clock = clock;
        rr$39$clock = clock;
        gr$39$clock = clock;
        br$39$clock = clock;
        wes$39$clock = clock;
        ozr$39$d = ozr$39$q;
        nzr$39$d = nzr$39$q;
        rr$39$d = rr$39$q;
        gr$39$d = gr$39$q;
        br$39$d = br$39$q;
        wes$39$d = wes$39$q;
        zc$40$clock = clock;
        ozr$40$clock = clock;
        nzr$40$clock = clock;
        rr$40$clock = clock;
        gr$40$clock = clock;
        br$40$clock = clock;
        wes$40$clock = clock;
        ozr$40$d = ozr$40$q;
        nzr$40$d = nzr$40$q;
        rr$40$d = rr$40$q;
        gr$40$d = gr$40$q;
        br$40$d = br$40$q;
        wes$40$d = wes$40$q;
        zc$41$clock = clock;
        ozr$41$clock = clock;
        nzr$41$clock = clock;
        rr$41$clock = clock;
        gr$41$clock = clock;
        br$41$clock = clock;
        wes$41$clock = clock;
        ozr$41$d = ozr$41$q;
        nzr$41$d = nzr$41$q;
        rr$41$d = rr$41$q;
        gr$41$d = gr$41$q;
        br$41$d = br$41$q;
        wes$41$d = wes$41$q;
        zc$42$clock = clock;
        ozr$42$clock = clock;
        nzr$42$clock = clock;
        rr$42$clock = clock;
        gr$42$clock = clock;
        br$42$clock = clock;
        wes$42$clock = clock;
        ozr$42$d = ozr$42$q;
        nzr$42$d = nzr$42$q;
        rr$42$d = rr$42$q;
        gr$42$d = gr$42$q;
        br$42$d = br$42$q;
        wes$42$d = wes$42$q;
        zc$43$clock = clock;
        ozr$43$clock = clock;
        nzr$43$clock = clock;
        rr$43$clock = clock;
        gr$43$clock = clock;
        br$43$clock = clock;
        wes$43$clock = clock;
        ozr$43$d = ozr$43$q;
        nzr$43$d = nzr$43$q;
        rr$43$d = rr$43$q;
        gr$43$d = gr$43$q;
        br$43$d = br$43$q;
        wes$43$d = wes$43$q;
        zc$44$clock = clock;
        ozr$44$clock = clock;
        nzr$44$clock = clock;
        rr$44$clock = clock;
        gr$44$clock = clock;
        br$44$clock = clock;
        wes$44$clock = clock;
        ozr$44$d = ozr$44$q;
        nzr$44$d = nzr$44$q;
        rr$44$d = rr$44$q;
        gr$44$d = gr$44$q;
        br$44$d = br$44$q;
        wes$44$d = wes$44$q;
        zc$45$clock = clock;
        ozr$45$clock = clock;
        nzr$45$clock = clock;
        rr$45$clock = clock;
        gr$45$clock = clock;
        br$45$clock = clock;
        wes$45$clock = clock;
        ozr$45$d = ozr$45$q;
        nzr$45$d = nzr$45$q;
        rr$45$d = rr$45$q;
        gr$45$d = gr$45$q;
        br$45$d = br$45$q;
        wes$45$d = wes$45$q;
        zc$46$clock = clock;
        ozr$46$clock = clock;
        nzr$46$clock = clock;
        rr$46$clock = clock;
        gr$46$clock = clock;
        br$46$clock = clock;
        wes$46$clock = clock;
        ozr$46$d = ozr$46$q;
        nzr$46$d = nzr$46$q;
        rr$46$d = rr$46$q;
        gr$46$d = gr$46$q;
        br$46$d = br$46$q;
        wes$46$d = wes$46$q;
        zc$47$clock = clock;
        ozr$47$clock = clock;
        nzr$47$clock = clock;
        rr$47$clock = clock;
        gr$47$clock = clock;
        br$47$clock = clock;
        wes$47$clock = clock;
        ozr$47$d = ozr$47$q;
        nzr$47$d = nzr$47$q;
        rr$47$d = rr$47$q;
        gr$47$d = gr$47$q;
        br$47$d = br$47$q;
        wes$47$d = wes$47$q;
        zc$48$clock = clock;
        ozr$48$clock = clock;
        nzr$48$clock = clock;
        rr$48$clock = clock;
        gr$48$clock = clock;
        br$48$clock = clock;
        wes$48$clock = clock;
        ozr$48$d = ozr$48$q;
        nzr$48$d = nzr$48$q;
        rr$48$d = rr$48$q;
        gr$48$d = gr$48$q;
        br$48$d = br$48$q;
        wes$48$d = wes$48$q;
        zc$49$clock = clock;
        ozr$49$clock = clock;
        nzr$49$clock = clock;
        rr$49$clock = clock;
        gr$49$clock = clock;
        br$49$clock = clock;
        wes$49$clock = clock;
        ozr$49$d = ozr$49$q;
        nzr$49$d = nzr$49$q;
        rr$49$d = rr$49$q;
        gr$49$d = gr$49$q;
        br$49$d = br$49$q;
        wes$49$d = wes$49$q;
        zc$50$clock = clock;
        ozr$50$clock = clock;
        nzr$50$clock = clock;
        rr$50$clock = clock;
        gr$50$clock = clock;
        br$50$clock = clock;
        wes$50$clock = clock;
        ozr$50$d = ozr$50$q;
        nzr$50$d = nzr$50$q;
        rr$50$d = rr$50$q;
        gr$50$d = gr$50$q;
        br$50$d = br$50$q;
        wes$50$d = wes$50$q;
        zc$51$clock = clock;
        ozr$51$clock = clock;
        nzr$51$clock = clock;
        rr$51$clock = clock;
        gr$51$clock = clock;
        br$51$clock = clock;
        wes$51$clock = clock;
        ozr$51$d = ozr$51$q;
        nzr$51$d = nzr$51$q;
        rr$51$d = rr$51$q;
        gr$51$d = gr$51$q;
        br$51$d = br$51$q;
        wes$51$d = wes$51$q;
        zc$52$clock = clock;
        ozr$52$clock = clock;
        nzr$52$clock = clock;
        rr$52$clock = clock;
        gr$52$clock = clock;
        br$52$clock = clock;
        wes$52$clock = clock;
        ozr$52$d = ozr$52$q;
        nzr$52$d = nzr$52$q;
        rr$52$d = rr$52$q;
        gr$52$d = gr$52$q;
        br$52$d = br$52$q;
        wes$52$d = wes$52$q;
        zc$53$clock = clock;
        ozr$53$clock = clock;
        nzr$53$clock = clock;
        rr$53$clock = clock;
        gr$53$clock = clock;
        br$53$clock = clock;
        wes$53$clock = clock;
        ozr$53$d = ozr$53$q;
        nzr$53$d = nzr$53$q;
        rr$53$d = rr$53$q;
        gr$53$d = gr$53$q;
        br$53$d = br$53$q;
        wes$53$d = wes$53$q;
        zc$54$clock = clock;
        ozr$54$clock = clock;
        nzr$54$clock = clock;
        rr$54$clock = clock;
        gr$54$clock = clock;
        br$54$clock = clock;
        wes$54$clock = clock;
        ozr$54$d = ozr$54$q;
        nzr$54$d = nzr$54$q;
        rr$54$d = rr$54$q;
        gr$54$d = gr$54$q;
        br$54$d = br$54$q;
        wes$54$d = wes$54$q;
        zc$55$clock = clock;
        ozr$55$clock = clock;
        nzr$55$clock = clock;
        rr$55$clock = clock;
        gr$55$clock = clock;
        br$55$clock = clock;
        wes$55$clock = clock;
        ozr$55$d = ozr$55$q;
        nzr$55$d = nzr$55$q;
        rr$55$d = rr$55$q;
        gr$55$d = gr$55$q;
        br$55$d = br$55$q;
        wes$55$d = wes$55$q;
        zc$56$clock = clock;
        ozr$56$clock = clock;
        nzr$56$clock = clock;
        rr$56$clock = clock;
        gr$56$clock = clock;
        br$56$clock = clock;
        wes$56$clock = clock;
        ozr$56$d = ozr$56$q;
        nzr$56$d = nzr$56$q;
        rr$56$d = rr$56$q;
        gr$56$d = gr$56$q;
        br$56$d = br$56$q;
        wes$56$d = wes$56$q;
        zc$57$clock = clock;
        ozr$57$clock = clock;
        nzr$57$clock = clock;
        rr$57$clock = clock;
        gr$57$clock = clock;
        br$57$clock = clock;
        wes$57$clock = clock;
        ozr$57$d = ozr$57$q;
        nzr$57$d = nzr$57$q;
        rr$57$d = rr$57$q;
        gr$57$d = gr$57$q;
        br$57$d = br$57$q;
        wes$57$d = wes$57$q;
        zc$58$clock = clock;
        ozr$58$clock = clock;
        nzr$58$clock = clock;
        rr$58$clock = clock;
        gr$58$clock = clock;
        br$58$clock = clock;
        wes$58$clock = clock;
        ozr$58$d = ozr$58$q;
        nzr$58$d = nzr$58$q;
        rr$58$d = rr$58$q;
        gr$58$d = gr$58$q;
        br$58$d = br$58$q;
        wes$58$d = wes$58$q;
        zc$59$clock = clock;
        ozr$59$clock = clock;
        nzr$59$clock = clock;
        rr$59$clock = clock;
        gr$59$clock = clock;
        br$59$clock = clock;
        wes$59$clock = clock;
        ozr$59$d = ozr$59$q;
        nzr$59$d = nzr$59$q;
        rr$59$d = rr$59$q;
        gr$59$d = gr$59$q;
        br$59$d = br$59$q;
        wes$59$d = wes$59$q;
        zc$60$clock = clock;
        ozr$60$clock = clock;
        nzr$60$clock = clock;
        rr$60$clock = clock;
        gr$60$clock = clock;
        br$60$clock = clock;
        wes$60$clock = clock;
        ozr$60$d = ozr$60$q;
        nzr$60$d = nzr$60$q;
        rr$60$d = rr$60$q;
        gr$60$d = gr$60$q;
        br$60$d = br$60$q;
        wes$60$d = wes$60$q;
        zc$61$clock = clock;
        ozr$61$clock = clock;
        nzr$61$clock = clock;
        rr$61$clock = clock;
        gr$61$clock = clock;
        br$61$clock = clock;
        wes$61$clock = clock;
        ozr$61$d = ozr$61$q;
        nzr$61$d = nzr$61$q;
        rr$61$d = rr$61$q;
        gr$61$d = gr$61$q;
        br$61$d = br$61$q;
        wes$61$d = wes$61$q;
        zc$62$clock = clock;
        ozr$62$clock = clock;
        nzr$62$clock = clock;
        rr$62$clock = clock;
        gr$62$clock = clock;
        br$62$clock = clock;
        wes$62$clock = clock;
        ozr$62$d = ozr$62$q;
        nzr$62$d = nzr$62$q;
        rr$62$d = rr$62$q;
        gr$62$d = gr$62$q;
        br$62$d = br$62$q;
        wes$62$d = wes$62$q;
        zc$63$clock = clock;
        ozr$63$clock = clock;
        nzr$63$clock = clock;
        rr$63$clock = clock;
        gr$63$clock = clock;
        br$63$clock = clock;
        wes$63$clock = clock;
        ozr$63$d = ozr$63$q;
        nzr$63$d = nzr$63$q;
        rr$63$d = rr$63$q;
        gr$63$d = gr$63$q;
        br$63$d = br$63$q;
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
        zc$0$first = zfirst;
        zc$0$nz = interp$px[0];
        zc$0$oz = ozr$0$q[32'h0];
        if (zwin) begin
            ozr$0$d = ozr$0$q >> 32'h1;
            nzr$0$d = nzr$0$q >> 32'h1;
            if (interp$px[0]) begin
                nzr$0$d = (nzr$0$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$0$d = rr$0$q >> 32'h1;
            if (interp$px[0]) begin
                rr$0$d = (rr$0$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$0$d = gr$0$q >> 32'h1;
            if (interp$px[0]) begin
                gr$0$d = (gr$0$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$0$d = br$0$q >> 32'h1;
            if (interp$px[0]) begin
                br$0$d = (br$0$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$0$d = mask[0] & zc$0$closer;
        end
        zc$1$first = zfirst;
        zc$1$nz = interp$px[1];
        zc$1$oz = ozr$1$q[32'h0];
        if (zwin) begin
            ozr$1$d = ozr$1$q >> 32'h1;
            nzr$1$d = nzr$1$q >> 32'h1;
            if (interp$px[1]) begin
                nzr$1$d = (nzr$1$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$1$d = rr$1$q >> 32'h1;
            if (interp$px[1]) begin
                rr$1$d = (rr$1$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$1$d = gr$1$q >> 32'h1;
            if (interp$px[1]) begin
                gr$1$d = (gr$1$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$1$d = br$1$q >> 32'h1;
            if (interp$px[1]) begin
                br$1$d = (br$1$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$1$d = mask[1] & zc$1$closer;
        end
        zc$2$first = zfirst;
        zc$2$nz = interp$px[2];
        zc$2$oz = ozr$2$q[32'h0];
        if (zwin) begin
            ozr$2$d = ozr$2$q >> 32'h1;
            nzr$2$d = nzr$2$q >> 32'h1;
            if (interp$px[2]) begin
                nzr$2$d = (nzr$2$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$2$d = rr$2$q >> 32'h1;
            if (interp$px[2]) begin
                rr$2$d = (rr$2$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$2$d = gr$2$q >> 32'h1;
            if (interp$px[2]) begin
                gr$2$d = (gr$2$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$2$d = br$2$q >> 32'h1;
            if (interp$px[2]) begin
                br$2$d = (br$2$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$2$d = mask[2] & zc$2$closer;
        end
        zc$3$first = zfirst;
        zc$3$nz = interp$px[3];
        zc$3$oz = ozr$3$q[32'h0];
        if (zwin) begin
            ozr$3$d = ozr$3$q >> 32'h1;
            nzr$3$d = nzr$3$q >> 32'h1;
            if (interp$px[3]) begin
                nzr$3$d = (nzr$3$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$3$d = rr$3$q >> 32'h1;
            if (interp$px[3]) begin
                rr$3$d = (rr$3$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$3$d = gr$3$q >> 32'h1;
            if (interp$px[3]) begin
                gr$3$d = (gr$3$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$3$d = br$3$q >> 32'h1;
            if (interp$px[3]) begin
                br$3$d = (br$3$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$3$d = mask[3] & zc$3$closer;
        end
        zc$4$first = zfirst;
        zc$4$nz = interp$px[4];
        zc$4$oz = ozr$4$q[32'h0];
        if (zwin) begin
            ozr$4$d = ozr$4$q >> 32'h1;
            nzr$4$d = nzr$4$q >> 32'h1;
            if (interp$px[4]) begin
                nzr$4$d = (nzr$4$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$4$d = rr$4$q >> 32'h1;
            if (interp$px[4]) begin
                rr$4$d = (rr$4$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$4$d = gr$4$q >> 32'h1;
            if (interp$px[4]) begin
                gr$4$d = (gr$4$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$4$d = br$4$q >> 32'h1;
            if (interp$px[4]) begin
                br$4$d = (br$4$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$4$d = mask[4] & zc$4$closer;
        end
        zc$5$first = zfirst;
        zc$5$nz = interp$px[5];
        zc$5$oz = ozr$5$q[32'h0];
        if (zwin) begin
            ozr$5$d = ozr$5$q >> 32'h1;
            nzr$5$d = nzr$5$q >> 32'h1;
            if (interp$px[5]) begin
                nzr$5$d = (nzr$5$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$5$d = rr$5$q >> 32'h1;
            if (interp$px[5]) begin
                rr$5$d = (rr$5$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$5$d = gr$5$q >> 32'h1;
            if (interp$px[5]) begin
                gr$5$d = (gr$5$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$5$d = br$5$q >> 32'h1;
            if (interp$px[5]) begin
                br$5$d = (br$5$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$5$d = mask[5] & zc$5$closer;
        end
        zc$6$first = zfirst;
        zc$6$nz = interp$px[6];
        zc$6$oz = ozr$6$q[32'h0];
        if (zwin) begin
            ozr$6$d = ozr$6$q >> 32'h1;
            nzr$6$d = nzr$6$q >> 32'h1;
            if (interp$px[6]) begin
                nzr$6$d = (nzr$6$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$6$d = rr$6$q >> 32'h1;
            if (interp$px[6]) begin
                rr$6$d = (rr$6$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$6$d = gr$6$q >> 32'h1;
            if (interp$px[6]) begin
                gr$6$d = (gr$6$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$6$d = br$6$q >> 32'h1;
            if (interp$px[6]) begin
                br$6$d = (br$6$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$6$d = mask[6] & zc$6$closer;
        end
        zc$7$first = zfirst;
        zc$7$nz = interp$px[7];
        zc$7$oz = ozr$7$q[32'h0];
        if (zwin) begin
            ozr$7$d = ozr$7$q >> 32'h1;
            nzr$7$d = nzr$7$q >> 32'h1;
            if (interp$px[7]) begin
                nzr$7$d = (nzr$7$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$7$d = rr$7$q >> 32'h1;
            if (interp$px[7]) begin
                rr$7$d = (rr$7$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$7$d = gr$7$q >> 32'h1;
            if (interp$px[7]) begin
                gr$7$d = (gr$7$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$7$d = br$7$q >> 32'h1;
            if (interp$px[7]) begin
                br$7$d = (br$7$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$7$d = mask[7] & zc$7$closer;
        end
        zc$8$first = zfirst;
        zc$8$nz = interp$px[8];
        zc$8$oz = ozr$8$q[32'h0];
        if (zwin) begin
            ozr$8$d = ozr$8$q >> 32'h1;
            nzr$8$d = nzr$8$q >> 32'h1;
            if (interp$px[8]) begin
                nzr$8$d = (nzr$8$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$8$d = rr$8$q >> 32'h1;
            if (interp$px[8]) begin
                rr$8$d = (rr$8$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$8$d = gr$8$q >> 32'h1;
            if (interp$px[8]) begin
                gr$8$d = (gr$8$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$8$d = br$8$q >> 32'h1;
            if (interp$px[8]) begin
                br$8$d = (br$8$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$8$d = mask[8] & zc$8$closer;
        end
        zc$9$first = zfirst;
        zc$9$nz = interp$px[9];
        zc$9$oz = ozr$9$q[32'h0];
        if (zwin) begin
            ozr$9$d = ozr$9$q >> 32'h1;
            nzr$9$d = nzr$9$q >> 32'h1;
            if (interp$px[9]) begin
                nzr$9$d = (nzr$9$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$9$d = rr$9$q >> 32'h1;
            if (interp$px[9]) begin
                rr$9$d = (rr$9$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$9$d = gr$9$q >> 32'h1;
            if (interp$px[9]) begin
                gr$9$d = (gr$9$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$9$d = br$9$q >> 32'h1;
            if (interp$px[9]) begin
                br$9$d = (br$9$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$9$d = mask[9] & zc$9$closer;
        end
        zc$10$first = zfirst;
        zc$10$nz = interp$px[10];
        zc$10$oz = ozr$10$q[32'h0];
        if (zwin) begin
            ozr$10$d = ozr$10$q >> 32'h1;
            nzr$10$d = nzr$10$q >> 32'h1;
            if (interp$px[10]) begin
                nzr$10$d = (nzr$10$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$10$d = rr$10$q >> 32'h1;
            if (interp$px[10]) begin
                rr$10$d = (rr$10$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$10$d = gr$10$q >> 32'h1;
            if (interp$px[10]) begin
                gr$10$d = (gr$10$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$10$d = br$10$q >> 32'h1;
            if (interp$px[10]) begin
                br$10$d = (br$10$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$10$d = mask[10] & zc$10$closer;
        end
        zc$11$first = zfirst;
        zc$11$nz = interp$px[11];
        zc$11$oz = ozr$11$q[32'h0];
        if (zwin) begin
            ozr$11$d = ozr$11$q >> 32'h1;
            nzr$11$d = nzr$11$q >> 32'h1;
            if (interp$px[11]) begin
                nzr$11$d = (nzr$11$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$11$d = rr$11$q >> 32'h1;
            if (interp$px[11]) begin
                rr$11$d = (rr$11$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$11$d = gr$11$q >> 32'h1;
            if (interp$px[11]) begin
                gr$11$d = (gr$11$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$11$d = br$11$q >> 32'h1;
            if (interp$px[11]) begin
                br$11$d = (br$11$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$11$d = mask[11] & zc$11$closer;
        end
        zc$12$first = zfirst;
        zc$12$nz = interp$px[12];
        zc$12$oz = ozr$12$q[32'h0];
        if (zwin) begin
            ozr$12$d = ozr$12$q >> 32'h1;
            nzr$12$d = nzr$12$q >> 32'h1;
            if (interp$px[12]) begin
                nzr$12$d = (nzr$12$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$12$d = rr$12$q >> 32'h1;
            if (interp$px[12]) begin
                rr$12$d = (rr$12$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$12$d = gr$12$q >> 32'h1;
            if (interp$px[12]) begin
                gr$12$d = (gr$12$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$12$d = br$12$q >> 32'h1;
            if (interp$px[12]) begin
                br$12$d = (br$12$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$12$d = mask[12] & zc$12$closer;
        end
        zc$13$first = zfirst;
        zc$13$nz = interp$px[13];
        zc$13$oz = ozr$13$q[32'h0];
        if (zwin) begin
            ozr$13$d = ozr$13$q >> 32'h1;
            nzr$13$d = nzr$13$q >> 32'h1;
            if (interp$px[13]) begin
                nzr$13$d = (nzr$13$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$13$d = rr$13$q >> 32'h1;
            if (interp$px[13]) begin
                rr$13$d = (rr$13$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$13$d = gr$13$q >> 32'h1;
            if (interp$px[13]) begin
                gr$13$d = (gr$13$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$13$d = br$13$q >> 32'h1;
            if (interp$px[13]) begin
                br$13$d = (br$13$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$13$d = mask[13] & zc$13$closer;
        end
        zc$14$first = zfirst;
        zc$14$nz = interp$px[14];
        zc$14$oz = ozr$14$q[32'h0];
        if (zwin) begin
            ozr$14$d = ozr$14$q >> 32'h1;
            nzr$14$d = nzr$14$q >> 32'h1;
            if (interp$px[14]) begin
                nzr$14$d = (nzr$14$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$14$d = rr$14$q >> 32'h1;
            if (interp$px[14]) begin
                rr$14$d = (rr$14$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$14$d = gr$14$q >> 32'h1;
            if (interp$px[14]) begin
                gr$14$d = (gr$14$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$14$d = br$14$q >> 32'h1;
            if (interp$px[14]) begin
                br$14$d = (br$14$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$14$d = mask[14] & zc$14$closer;
        end
        zc$15$first = zfirst;
        zc$15$nz = interp$px[15];
        zc$15$oz = ozr$15$q[32'h0];
        if (zwin) begin
            ozr$15$d = ozr$15$q >> 32'h1;
            nzr$15$d = nzr$15$q >> 32'h1;
            if (interp$px[15]) begin
                nzr$15$d = (nzr$15$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$15$d = rr$15$q >> 32'h1;
            if (interp$px[15]) begin
                rr$15$d = (rr$15$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$15$d = gr$15$q >> 32'h1;
            if (interp$px[15]) begin
                gr$15$d = (gr$15$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$15$d = br$15$q >> 32'h1;
            if (interp$px[15]) begin
                br$15$d = (br$15$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$15$d = mask[15] & zc$15$closer;
        end
        zc$16$first = zfirst;
        zc$16$nz = interp$px[16];
        zc$16$oz = ozr$16$q[32'h0];
        if (zwin) begin
            ozr$16$d = ozr$16$q >> 32'h1;
            nzr$16$d = nzr$16$q >> 32'h1;
            if (interp$px[16]) begin
                nzr$16$d = (nzr$16$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$16$d = rr$16$q >> 32'h1;
            if (interp$px[16]) begin
                rr$16$d = (rr$16$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$16$d = gr$16$q >> 32'h1;
            if (interp$px[16]) begin
                gr$16$d = (gr$16$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$16$d = br$16$q >> 32'h1;
            if (interp$px[16]) begin
                br$16$d = (br$16$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$16$d = mask[16] & zc$16$closer;
        end
        zc$17$first = zfirst;
        zc$17$nz = interp$px[17];
        zc$17$oz = ozr$17$q[32'h0];
        if (zwin) begin
            ozr$17$d = ozr$17$q >> 32'h1;
            nzr$17$d = nzr$17$q >> 32'h1;
            if (interp$px[17]) begin
                nzr$17$d = (nzr$17$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$17$d = rr$17$q >> 32'h1;
            if (interp$px[17]) begin
                rr$17$d = (rr$17$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$17$d = gr$17$q >> 32'h1;
            if (interp$px[17]) begin
                gr$17$d = (gr$17$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$17$d = br$17$q >> 32'h1;
            if (interp$px[17]) begin
                br$17$d = (br$17$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$17$d = mask[17] & zc$17$closer;
        end
        zc$18$first = zfirst;
        zc$18$nz = interp$px[18];
        zc$18$oz = ozr$18$q[32'h0];
        if (zwin) begin
            ozr$18$d = ozr$18$q >> 32'h1;
            nzr$18$d = nzr$18$q >> 32'h1;
            if (interp$px[18]) begin
                nzr$18$d = (nzr$18$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$18$d = rr$18$q >> 32'h1;
            if (interp$px[18]) begin
                rr$18$d = (rr$18$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$18$d = gr$18$q >> 32'h1;
            if (interp$px[18]) begin
                gr$18$d = (gr$18$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$18$d = br$18$q >> 32'h1;
            if (interp$px[18]) begin
                br$18$d = (br$18$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$18$d = mask[18] & zc$18$closer;
        end
        zc$19$first = zfirst;
        zc$19$nz = interp$px[19];
        zc$19$oz = ozr$19$q[32'h0];
        if (zwin) begin
            ozr$19$d = ozr$19$q >> 32'h1;
            nzr$19$d = nzr$19$q >> 32'h1;
            if (interp$px[19]) begin
                nzr$19$d = (nzr$19$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$19$d = rr$19$q >> 32'h1;
            if (interp$px[19]) begin
                rr$19$d = (rr$19$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$19$d = gr$19$q >> 32'h1;
            if (interp$px[19]) begin
                gr$19$d = (gr$19$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$19$d = br$19$q >> 32'h1;
            if (interp$px[19]) begin
                br$19$d = (br$19$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$19$d = mask[19] & zc$19$closer;
        end
        zc$20$first = zfirst;
        zc$20$nz = interp$px[20];
        zc$20$oz = ozr$20$q[32'h0];
        if (zwin) begin
            ozr$20$d = ozr$20$q >> 32'h1;
            nzr$20$d = nzr$20$q >> 32'h1;
            if (interp$px[20]) begin
                nzr$20$d = (nzr$20$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$20$d = rr$20$q >> 32'h1;
            if (interp$px[20]) begin
                rr$20$d = (rr$20$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$20$d = gr$20$q >> 32'h1;
            if (interp$px[20]) begin
                gr$20$d = (gr$20$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$20$d = br$20$q >> 32'h1;
            if (interp$px[20]) begin
                br$20$d = (br$20$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$20$d = mask[20] & zc$20$closer;
        end
        zc$21$first = zfirst;
        zc$21$nz = interp$px[21];
        zc$21$oz = ozr$21$q[32'h0];
        if (zwin) begin
            ozr$21$d = ozr$21$q >> 32'h1;
            nzr$21$d = nzr$21$q >> 32'h1;
            if (interp$px[21]) begin
                nzr$21$d = (nzr$21$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$21$d = rr$21$q >> 32'h1;
            if (interp$px[21]) begin
                rr$21$d = (rr$21$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$21$d = gr$21$q >> 32'h1;
            if (interp$px[21]) begin
                gr$21$d = (gr$21$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$21$d = br$21$q >> 32'h1;
            if (interp$px[21]) begin
                br$21$d = (br$21$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$21$d = mask[21] & zc$21$closer;
        end
        zc$22$first = zfirst;
        zc$22$nz = interp$px[22];
        zc$22$oz = ozr$22$q[32'h0];
        if (zwin) begin
            ozr$22$d = ozr$22$q >> 32'h1;
            nzr$22$d = nzr$22$q >> 32'h1;
            if (interp$px[22]) begin
                nzr$22$d = (nzr$22$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$22$d = rr$22$q >> 32'h1;
            if (interp$px[22]) begin
                rr$22$d = (rr$22$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$22$d = gr$22$q >> 32'h1;
            if (interp$px[22]) begin
                gr$22$d = (gr$22$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$22$d = br$22$q >> 32'h1;
            if (interp$px[22]) begin
                br$22$d = (br$22$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$22$d = mask[22] & zc$22$closer;
        end
        zc$23$first = zfirst;
        zc$23$nz = interp$px[23];
        zc$23$oz = ozr$23$q[32'h0];
        if (zwin) begin
            ozr$23$d = ozr$23$q >> 32'h1;
            nzr$23$d = nzr$23$q >> 32'h1;
            if (interp$px[23]) begin
                nzr$23$d = (nzr$23$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$23$d = rr$23$q >> 32'h1;
            if (interp$px[23]) begin
                rr$23$d = (rr$23$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$23$d = gr$23$q >> 32'h1;
            if (interp$px[23]) begin
                gr$23$d = (gr$23$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$23$d = br$23$q >> 32'h1;
            if (interp$px[23]) begin
                br$23$d = (br$23$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$23$d = mask[23] & zc$23$closer;
        end
        zc$24$first = zfirst;
        zc$24$nz = interp$px[24];
        zc$24$oz = ozr$24$q[32'h0];
        if (zwin) begin
            ozr$24$d = ozr$24$q >> 32'h1;
            nzr$24$d = nzr$24$q >> 32'h1;
            if (interp$px[24]) begin
                nzr$24$d = (nzr$24$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$24$d = rr$24$q >> 32'h1;
            if (interp$px[24]) begin
                rr$24$d = (rr$24$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$24$d = gr$24$q >> 32'h1;
            if (interp$px[24]) begin
                gr$24$d = (gr$24$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$24$d = br$24$q >> 32'h1;
            if (interp$px[24]) begin
                br$24$d = (br$24$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$24$d = mask[24] & zc$24$closer;
        end
        zc$25$first = zfirst;
        zc$25$nz = interp$px[25];
        zc$25$oz = ozr$25$q[32'h0];
        if (zwin) begin
            ozr$25$d = ozr$25$q >> 32'h1;
            nzr$25$d = nzr$25$q >> 32'h1;
            if (interp$px[25]) begin
                nzr$25$d = (nzr$25$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$25$d = rr$25$q >> 32'h1;
            if (interp$px[25]) begin
                rr$25$d = (rr$25$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$25$d = gr$25$q >> 32'h1;
            if (interp$px[25]) begin
                gr$25$d = (gr$25$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$25$d = br$25$q >> 32'h1;
            if (interp$px[25]) begin
                br$25$d = (br$25$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$25$d = mask[25] & zc$25$closer;
        end
        zc$26$first = zfirst;
        zc$26$nz = interp$px[26];
        zc$26$oz = ozr$26$q[32'h0];
        if (zwin) begin
            ozr$26$d = ozr$26$q >> 32'h1;
            nzr$26$d = nzr$26$q >> 32'h1;
            if (interp$px[26]) begin
                nzr$26$d = (nzr$26$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$26$d = rr$26$q >> 32'h1;
            if (interp$px[26]) begin
                rr$26$d = (rr$26$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$26$d = gr$26$q >> 32'h1;
            if (interp$px[26]) begin
                gr$26$d = (gr$26$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$26$d = br$26$q >> 32'h1;
            if (interp$px[26]) begin
                br$26$d = (br$26$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$26$d = mask[26] & zc$26$closer;
        end
        zc$27$first = zfirst;
        zc$27$nz = interp$px[27];
        zc$27$oz = ozr$27$q[32'h0];
        if (zwin) begin
            ozr$27$d = ozr$27$q >> 32'h1;
            nzr$27$d = nzr$27$q >> 32'h1;
            if (interp$px[27]) begin
                nzr$27$d = (nzr$27$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$27$d = rr$27$q >> 32'h1;
            if (interp$px[27]) begin
                rr$27$d = (rr$27$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$27$d = gr$27$q >> 32'h1;
            if (interp$px[27]) begin
                gr$27$d = (gr$27$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$27$d = br$27$q >> 32'h1;
            if (interp$px[27]) begin
                br$27$d = (br$27$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$27$d = mask[27] & zc$27$closer;
        end
        zc$28$first = zfirst;
        zc$28$nz = interp$px[28];
        zc$28$oz = ozr$28$q[32'h0];
        if (zwin) begin
            ozr$28$d = ozr$28$q >> 32'h1;
            nzr$28$d = nzr$28$q >> 32'h1;
            if (interp$px[28]) begin
                nzr$28$d = (nzr$28$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$28$d = rr$28$q >> 32'h1;
            if (interp$px[28]) begin
                rr$28$d = (rr$28$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$28$d = gr$28$q >> 32'h1;
            if (interp$px[28]) begin
                gr$28$d = (gr$28$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$28$d = br$28$q >> 32'h1;
            if (interp$px[28]) begin
                br$28$d = (br$28$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$28$d = mask[28] & zc$28$closer;
        end
        zc$29$first = zfirst;
        zc$29$nz = interp$px[29];
        zc$29$oz = ozr$29$q[32'h0];
        if (zwin) begin
            ozr$29$d = ozr$29$q >> 32'h1;
            nzr$29$d = nzr$29$q >> 32'h1;
            if (interp$px[29]) begin
                nzr$29$d = (nzr$29$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$29$d = rr$29$q >> 32'h1;
            if (interp$px[29]) begin
                rr$29$d = (rr$29$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$29$d = gr$29$q >> 32'h1;
            if (interp$px[29]) begin
                gr$29$d = (gr$29$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$29$d = br$29$q >> 32'h1;
            if (interp$px[29]) begin
                br$29$d = (br$29$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$29$d = mask[29] & zc$29$closer;
        end
        zc$30$first = zfirst;
        zc$30$nz = interp$px[30];
        zc$30$oz = ozr$30$q[32'h0];
        if (zwin) begin
            ozr$30$d = ozr$30$q >> 32'h1;
            nzr$30$d = nzr$30$q >> 32'h1;
            if (interp$px[30]) begin
                nzr$30$d = (nzr$30$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$30$d = rr$30$q >> 32'h1;
            if (interp$px[30]) begin
                rr$30$d = (rr$30$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$30$d = gr$30$q >> 32'h1;
            if (interp$px[30]) begin
                gr$30$d = (gr$30$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$30$d = br$30$q >> 32'h1;
            if (interp$px[30]) begin
                br$30$d = (br$30$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$30$d = mask[30] & zc$30$closer;
        end
        zc$31$first = zfirst;
        zc$31$nz = interp$px[31];
        zc$31$oz = ozr$31$q[32'h0];
        if (zwin) begin
            ozr$31$d = ozr$31$q >> 32'h1;
            nzr$31$d = nzr$31$q >> 32'h1;
            if (interp$px[31]) begin
                nzr$31$d = (nzr$31$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$31$d = rr$31$q >> 32'h1;
            if (interp$px[31]) begin
                rr$31$d = (rr$31$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$31$d = gr$31$q >> 32'h1;
            if (interp$px[31]) begin
                gr$31$d = (gr$31$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$31$d = br$31$q >> 32'h1;
            if (interp$px[31]) begin
                br$31$d = (br$31$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$31$d = mask[31] & zc$31$closer;
        end
        zc$32$first = zfirst;
        zc$32$nz = interp$px[32];
        zc$32$oz = ozr$32$q[32'h0];
        if (zwin) begin
            ozr$32$d = ozr$32$q >> 32'h1;
            nzr$32$d = nzr$32$q >> 32'h1;
            if (interp$px[32]) begin
                nzr$32$d = (nzr$32$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$32$d = rr$32$q >> 32'h1;
            if (interp$px[32]) begin
                rr$32$d = (rr$32$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$32$d = gr$32$q >> 32'h1;
            if (interp$px[32]) begin
                gr$32$d = (gr$32$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$32$d = br$32$q >> 32'h1;
            if (interp$px[32]) begin
                br$32$d = (br$32$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$32$d = mask[32] & zc$32$closer;
        end
        zc$33$first = zfirst;
        zc$33$nz = interp$px[33];
        zc$33$oz = ozr$33$q[32'h0];
        if (zwin) begin
            ozr$33$d = ozr$33$q >> 32'h1;
            nzr$33$d = nzr$33$q >> 32'h1;
            if (interp$px[33]) begin
                nzr$33$d = (nzr$33$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$33$d = rr$33$q >> 32'h1;
            if (interp$px[33]) begin
                rr$33$d = (rr$33$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$33$d = gr$33$q >> 32'h1;
            if (interp$px[33]) begin
                gr$33$d = (gr$33$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$33$d = br$33$q >> 32'h1;
            if (interp$px[33]) begin
                br$33$d = (br$33$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$33$d = mask[33] & zc$33$closer;
        end
        zc$34$first = zfirst;
        zc$34$nz = interp$px[34];
        zc$34$oz = ozr$34$q[32'h0];
        if (zwin) begin
            ozr$34$d = ozr$34$q >> 32'h1;
            nzr$34$d = nzr$34$q >> 32'h1;
            if (interp$px[34]) begin
                nzr$34$d = (nzr$34$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$34$d = rr$34$q >> 32'h1;
            if (interp$px[34]) begin
                rr$34$d = (rr$34$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$34$d = gr$34$q >> 32'h1;
            if (interp$px[34]) begin
                gr$34$d = (gr$34$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$34$d = br$34$q >> 32'h1;
            if (interp$px[34]) begin
                br$34$d = (br$34$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$34$d = mask[34] & zc$34$closer;
        end
        zc$35$first = zfirst;
        zc$35$nz = interp$px[35];
        zc$35$oz = ozr$35$q[32'h0];
        if (zwin) begin
            ozr$35$d = ozr$35$q >> 32'h1;
            nzr$35$d = nzr$35$q >> 32'h1;
            if (interp$px[35]) begin
                nzr$35$d = (nzr$35$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$35$d = rr$35$q >> 32'h1;
            if (interp$px[35]) begin
                rr$35$d = (rr$35$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$35$d = gr$35$q >> 32'h1;
            if (interp$px[35]) begin
                gr$35$d = (gr$35$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$35$d = br$35$q >> 32'h1;
            if (interp$px[35]) begin
                br$35$d = (br$35$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$35$d = mask[35] & zc$35$closer;
        end
        zc$36$first = zfirst;
        zc$36$nz = interp$px[36];
        zc$36$oz = ozr$36$q[32'h0];
        if (zwin) begin
            ozr$36$d = ozr$36$q >> 32'h1;
            nzr$36$d = nzr$36$q >> 32'h1;
            if (interp$px[36]) begin
                nzr$36$d = (nzr$36$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$36$d = rr$36$q >> 32'h1;
            if (interp$px[36]) begin
                rr$36$d = (rr$36$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$36$d = gr$36$q >> 32'h1;
            if (interp$px[36]) begin
                gr$36$d = (gr$36$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$36$d = br$36$q >> 32'h1;
            if (interp$px[36]) begin
                br$36$d = (br$36$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$36$d = mask[36] & zc$36$closer;
        end
        zc$37$first = zfirst;
        zc$37$nz = interp$px[37];
        zc$37$oz = ozr$37$q[32'h0];
        if (zwin) begin
            ozr$37$d = ozr$37$q >> 32'h1;
            nzr$37$d = nzr$37$q >> 32'h1;
            if (interp$px[37]) begin
                nzr$37$d = (nzr$37$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$37$d = rr$37$q >> 32'h1;
            if (interp$px[37]) begin
                rr$37$d = (rr$37$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$37$d = gr$37$q >> 32'h1;
            if (interp$px[37]) begin
                gr$37$d = (gr$37$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$37$d = br$37$q >> 32'h1;
            if (interp$px[37]) begin
                br$37$d = (br$37$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$37$d = mask[37] & zc$37$closer;
        end
        zc$38$first = zfirst;
        zc$38$nz = interp$px[38];
        zc$38$oz = ozr$38$q[32'h0];
        if (zwin) begin
            ozr$38$d = ozr$38$q >> 32'h1;
            nzr$38$d = nzr$38$q >> 32'h1;
            if (interp$px[38]) begin
                nzr$38$d = (nzr$38$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$38$d = rr$38$q >> 32'h1;
            if (interp$px[38]) begin
                rr$38$d = (rr$38$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$38$d = gr$38$q >> 32'h1;
            if (interp$px[38]) begin
                gr$38$d = (gr$38$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$38$d = br$38$q >> 32'h1;
            if (interp$px[38]) begin
                br$38$d = (br$38$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$38$d = mask[38] & zc$38$closer;
        end
        zc$39$first = zfirst;
        zc$39$nz = interp$px[39];
        zc$39$oz = ozr$39$q[32'h0];
        if (zwin) begin
            ozr$39$d = ozr$39$q >> 32'h1;
            nzr$39$d = nzr$39$q >> 32'h1;
            if (interp$px[39]) begin
                nzr$39$d = (nzr$39$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$39$d = rr$39$q >> 32'h1;
            if (interp$px[39]) begin
                rr$39$d = (rr$39$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$39$d = gr$39$q >> 32'h1;
            if (interp$px[39]) begin
                gr$39$d = (gr$39$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$39$d = br$39$q >> 32'h1;
            if (interp$px[39]) begin
                br$39$d = (br$39$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$39$d = mask[39] & zc$39$closer;
        end
        zc$40$first = zfirst;
        zc$40$nz = interp$px[40];
        zc$40$oz = ozr$40$q[32'h0];
        if (zwin) begin
            ozr$40$d = ozr$40$q >> 32'h1;
            nzr$40$d = nzr$40$q >> 32'h1;
            if (interp$px[40]) begin
                nzr$40$d = (nzr$40$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$40$d = rr$40$q >> 32'h1;
            if (interp$px[40]) begin
                rr$40$d = (rr$40$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$40$d = gr$40$q >> 32'h1;
            if (interp$px[40]) begin
                gr$40$d = (gr$40$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$40$d = br$40$q >> 32'h1;
            if (interp$px[40]) begin
                br$40$d = (br$40$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$40$d = mask[40] & zc$40$closer;
        end
        zc$41$first = zfirst;
        zc$41$nz = interp$px[41];
        zc$41$oz = ozr$41$q[32'h0];
        if (zwin) begin
            ozr$41$d = ozr$41$q >> 32'h1;
            nzr$41$d = nzr$41$q >> 32'h1;
            if (interp$px[41]) begin
                nzr$41$d = (nzr$41$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$41$d = rr$41$q >> 32'h1;
            if (interp$px[41]) begin
                rr$41$d = (rr$41$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$41$d = gr$41$q >> 32'h1;
            if (interp$px[41]) begin
                gr$41$d = (gr$41$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$41$d = br$41$q >> 32'h1;
            if (interp$px[41]) begin
                br$41$d = (br$41$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$41$d = mask[41] & zc$41$closer;
        end
        zc$42$first = zfirst;
        zc$42$nz = interp$px[42];
        zc$42$oz = ozr$42$q[32'h0];
        if (zwin) begin
            ozr$42$d = ozr$42$q >> 32'h1;
            nzr$42$d = nzr$42$q >> 32'h1;
            if (interp$px[42]) begin
                nzr$42$d = (nzr$42$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$42$d = rr$42$q >> 32'h1;
            if (interp$px[42]) begin
                rr$42$d = (rr$42$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$42$d = gr$42$q >> 32'h1;
            if (interp$px[42]) begin
                gr$42$d = (gr$42$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$42$d = br$42$q >> 32'h1;
            if (interp$px[42]) begin
                br$42$d = (br$42$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$42$d = mask[42] & zc$42$closer;
        end
        zc$43$first = zfirst;
        zc$43$nz = interp$px[43];
        zc$43$oz = ozr$43$q[32'h0];
        if (zwin) begin
            ozr$43$d = ozr$43$q >> 32'h1;
            nzr$43$d = nzr$43$q >> 32'h1;
            if (interp$px[43]) begin
                nzr$43$d = (nzr$43$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$43$d = rr$43$q >> 32'h1;
            if (interp$px[43]) begin
                rr$43$d = (rr$43$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$43$d = gr$43$q >> 32'h1;
            if (interp$px[43]) begin
                gr$43$d = (gr$43$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$43$d = br$43$q >> 32'h1;
            if (interp$px[43]) begin
                br$43$d = (br$43$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$43$d = mask[43] & zc$43$closer;
        end
        zc$44$first = zfirst;
        zc$44$nz = interp$px[44];
        zc$44$oz = ozr$44$q[32'h0];
        if (zwin) begin
            ozr$44$d = ozr$44$q >> 32'h1;
            nzr$44$d = nzr$44$q >> 32'h1;
            if (interp$px[44]) begin
                nzr$44$d = (nzr$44$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$44$d = rr$44$q >> 32'h1;
            if (interp$px[44]) begin
                rr$44$d = (rr$44$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$44$d = gr$44$q >> 32'h1;
            if (interp$px[44]) begin
                gr$44$d = (gr$44$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$44$d = br$44$q >> 32'h1;
            if (interp$px[44]) begin
                br$44$d = (br$44$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$44$d = mask[44] & zc$44$closer;
        end
        zc$45$first = zfirst;
        zc$45$nz = interp$px[45];
        zc$45$oz = ozr$45$q[32'h0];
        if (zwin) begin
            ozr$45$d = ozr$45$q >> 32'h1;
            nzr$45$d = nzr$45$q >> 32'h1;
            if (interp$px[45]) begin
                nzr$45$d = (nzr$45$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$45$d = rr$45$q >> 32'h1;
            if (interp$px[45]) begin
                rr$45$d = (rr$45$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$45$d = gr$45$q >> 32'h1;
            if (interp$px[45]) begin
                gr$45$d = (gr$45$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$45$d = br$45$q >> 32'h1;
            if (interp$px[45]) begin
                br$45$d = (br$45$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$45$d = mask[45] & zc$45$closer;
        end
        zc$46$first = zfirst;
        zc$46$nz = interp$px[46];
        zc$46$oz = ozr$46$q[32'h0];
        if (zwin) begin
            ozr$46$d = ozr$46$q >> 32'h1;
            nzr$46$d = nzr$46$q >> 32'h1;
            if (interp$px[46]) begin
                nzr$46$d = (nzr$46$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$46$d = rr$46$q >> 32'h1;
            if (interp$px[46]) begin
                rr$46$d = (rr$46$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$46$d = gr$46$q >> 32'h1;
            if (interp$px[46]) begin
                gr$46$d = (gr$46$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$46$d = br$46$q >> 32'h1;
            if (interp$px[46]) begin
                br$46$d = (br$46$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$46$d = mask[46] & zc$46$closer;
        end
        zc$47$first = zfirst;
        zc$47$nz = interp$px[47];
        zc$47$oz = ozr$47$q[32'h0];
        if (zwin) begin
            ozr$47$d = ozr$47$q >> 32'h1;
            nzr$47$d = nzr$47$q >> 32'h1;
            if (interp$px[47]) begin
                nzr$47$d = (nzr$47$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$47$d = rr$47$q >> 32'h1;
            if (interp$px[47]) begin
                rr$47$d = (rr$47$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$47$d = gr$47$q >> 32'h1;
            if (interp$px[47]) begin
                gr$47$d = (gr$47$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$47$d = br$47$q >> 32'h1;
            if (interp$px[47]) begin
                br$47$d = (br$47$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$47$d = mask[47] & zc$47$closer;
        end
        zc$48$first = zfirst;
        zc$48$nz = interp$px[48];
        zc$48$oz = ozr$48$q[32'h0];
        if (zwin) begin
            ozr$48$d = ozr$48$q >> 32'h1;
            nzr$48$d = nzr$48$q >> 32'h1;
            if (interp$px[48]) begin
                nzr$48$d = (nzr$48$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$48$d = rr$48$q >> 32'h1;
            if (interp$px[48]) begin
                rr$48$d = (rr$48$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$48$d = gr$48$q >> 32'h1;
            if (interp$px[48]) begin
                gr$48$d = (gr$48$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$48$d = br$48$q >> 32'h1;
            if (interp$px[48]) begin
                br$48$d = (br$48$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$48$d = mask[48] & zc$48$closer;
        end
        zc$49$first = zfirst;
        zc$49$nz = interp$px[49];
        zc$49$oz = ozr$49$q[32'h0];
        if (zwin) begin
            ozr$49$d = ozr$49$q >> 32'h1;
            nzr$49$d = nzr$49$q >> 32'h1;
            if (interp$px[49]) begin
                nzr$49$d = (nzr$49$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$49$d = rr$49$q >> 32'h1;
            if (interp$px[49]) begin
                rr$49$d = (rr$49$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$49$d = gr$49$q >> 32'h1;
            if (interp$px[49]) begin
                gr$49$d = (gr$49$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$49$d = br$49$q >> 32'h1;
            if (interp$px[49]) begin
                br$49$d = (br$49$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$49$d = mask[49] & zc$49$closer;
        end
        zc$50$first = zfirst;
        zc$50$nz = interp$px[50];
        zc$50$oz = ozr$50$q[32'h0];
        if (zwin) begin
            ozr$50$d = ozr$50$q >> 32'h1;
            nzr$50$d = nzr$50$q >> 32'h1;
            if (interp$px[50]) begin
                nzr$50$d = (nzr$50$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$50$d = rr$50$q >> 32'h1;
            if (interp$px[50]) begin
                rr$50$d = (rr$50$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$50$d = gr$50$q >> 32'h1;
            if (interp$px[50]) begin
                gr$50$d = (gr$50$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$50$d = br$50$q >> 32'h1;
            if (interp$px[50]) begin
                br$50$d = (br$50$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$50$d = mask[50] & zc$50$closer;
        end
        zc$51$first = zfirst;
        zc$51$nz = interp$px[51];
        zc$51$oz = ozr$51$q[32'h0];
        if (zwin) begin
            ozr$51$d = ozr$51$q >> 32'h1;
            nzr$51$d = nzr$51$q >> 32'h1;
            if (interp$px[51]) begin
                nzr$51$d = (nzr$51$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$51$d = rr$51$q >> 32'h1;
            if (interp$px[51]) begin
                rr$51$d = (rr$51$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$51$d = gr$51$q >> 32'h1;
            if (interp$px[51]) begin
                gr$51$d = (gr$51$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$51$d = br$51$q >> 32'h1;
            if (interp$px[51]) begin
                br$51$d = (br$51$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$51$d = mask[51] & zc$51$closer;
        end
        zc$52$first = zfirst;
        zc$52$nz = interp$px[52];
        zc$52$oz = ozr$52$q[32'h0];
        if (zwin) begin
            ozr$52$d = ozr$52$q >> 32'h1;
            nzr$52$d = nzr$52$q >> 32'h1;
            if (interp$px[52]) begin
                nzr$52$d = (nzr$52$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$52$d = rr$52$q >> 32'h1;
            if (interp$px[52]) begin
                rr$52$d = (rr$52$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$52$d = gr$52$q >> 32'h1;
            if (interp$px[52]) begin
                gr$52$d = (gr$52$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$52$d = br$52$q >> 32'h1;
            if (interp$px[52]) begin
                br$52$d = (br$52$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$52$d = mask[52] & zc$52$closer;
        end
        zc$53$first = zfirst;
        zc$53$nz = interp$px[53];
        zc$53$oz = ozr$53$q[32'h0];
        if (zwin) begin
            ozr$53$d = ozr$53$q >> 32'h1;
            nzr$53$d = nzr$53$q >> 32'h1;
            if (interp$px[53]) begin
                nzr$53$d = (nzr$53$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$53$d = rr$53$q >> 32'h1;
            if (interp$px[53]) begin
                rr$53$d = (rr$53$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$53$d = gr$53$q >> 32'h1;
            if (interp$px[53]) begin
                gr$53$d = (gr$53$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$53$d = br$53$q >> 32'h1;
            if (interp$px[53]) begin
                br$53$d = (br$53$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$53$d = mask[53] & zc$53$closer;
        end
        zc$54$first = zfirst;
        zc$54$nz = interp$px[54];
        zc$54$oz = ozr$54$q[32'h0];
        if (zwin) begin
            ozr$54$d = ozr$54$q >> 32'h1;
            nzr$54$d = nzr$54$q >> 32'h1;
            if (interp$px[54]) begin
                nzr$54$d = (nzr$54$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$54$d = rr$54$q >> 32'h1;
            if (interp$px[54]) begin
                rr$54$d = (rr$54$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$54$d = gr$54$q >> 32'h1;
            if (interp$px[54]) begin
                gr$54$d = (gr$54$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$54$d = br$54$q >> 32'h1;
            if (interp$px[54]) begin
                br$54$d = (br$54$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$54$d = mask[54] & zc$54$closer;
        end
        zc$55$first = zfirst;
        zc$55$nz = interp$px[55];
        zc$55$oz = ozr$55$q[32'h0];
        if (zwin) begin
            ozr$55$d = ozr$55$q >> 32'h1;
            nzr$55$d = nzr$55$q >> 32'h1;
            if (interp$px[55]) begin
                nzr$55$d = (nzr$55$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$55$d = rr$55$q >> 32'h1;
            if (interp$px[55]) begin
                rr$55$d = (rr$55$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$55$d = gr$55$q >> 32'h1;
            if (interp$px[55]) begin
                gr$55$d = (gr$55$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$55$d = br$55$q >> 32'h1;
            if (interp$px[55]) begin
                br$55$d = (br$55$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$55$d = mask[55] & zc$55$closer;
        end
        zc$56$first = zfirst;
        zc$56$nz = interp$px[56];
        zc$56$oz = ozr$56$q[32'h0];
        if (zwin) begin
            ozr$56$d = ozr$56$q >> 32'h1;
            nzr$56$d = nzr$56$q >> 32'h1;
            if (interp$px[56]) begin
                nzr$56$d = (nzr$56$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$56$d = rr$56$q >> 32'h1;
            if (interp$px[56]) begin
                rr$56$d = (rr$56$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$56$d = gr$56$q >> 32'h1;
            if (interp$px[56]) begin
                gr$56$d = (gr$56$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$56$d = br$56$q >> 32'h1;
            if (interp$px[56]) begin
                br$56$d = (br$56$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$56$d = mask[56] & zc$56$closer;
        end
        zc$57$first = zfirst;
        zc$57$nz = interp$px[57];
        zc$57$oz = ozr$57$q[32'h0];
        if (zwin) begin
            ozr$57$d = ozr$57$q >> 32'h1;
            nzr$57$d = nzr$57$q >> 32'h1;
            if (interp$px[57]) begin
                nzr$57$d = (nzr$57$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$57$d = rr$57$q >> 32'h1;
            if (interp$px[57]) begin
                rr$57$d = (rr$57$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$57$d = gr$57$q >> 32'h1;
            if (interp$px[57]) begin
                gr$57$d = (gr$57$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$57$d = br$57$q >> 32'h1;
            if (interp$px[57]) begin
                br$57$d = (br$57$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$57$d = mask[57] & zc$57$closer;
        end
        zc$58$first = zfirst;
        zc$58$nz = interp$px[58];
        zc$58$oz = ozr$58$q[32'h0];
        if (zwin) begin
            ozr$58$d = ozr$58$q >> 32'h1;
            nzr$58$d = nzr$58$q >> 32'h1;
            if (interp$px[58]) begin
                nzr$58$d = (nzr$58$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$58$d = rr$58$q >> 32'h1;
            if (interp$px[58]) begin
                rr$58$d = (rr$58$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$58$d = gr$58$q >> 32'h1;
            if (interp$px[58]) begin
                gr$58$d = (gr$58$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$58$d = br$58$q >> 32'h1;
            if (interp$px[58]) begin
                br$58$d = (br$58$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$58$d = mask[58] & zc$58$closer;
        end
        zc$59$first = zfirst;
        zc$59$nz = interp$px[59];
        zc$59$oz = ozr$59$q[32'h0];
        if (zwin) begin
            ozr$59$d = ozr$59$q >> 32'h1;
            nzr$59$d = nzr$59$q >> 32'h1;
            if (interp$px[59]) begin
                nzr$59$d = (nzr$59$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$59$d = rr$59$q >> 32'h1;
            if (interp$px[59]) begin
                rr$59$d = (rr$59$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$59$d = gr$59$q >> 32'h1;
            if (interp$px[59]) begin
                gr$59$d = (gr$59$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$59$d = br$59$q >> 32'h1;
            if (interp$px[59]) begin
                br$59$d = (br$59$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$59$d = mask[59] & zc$59$closer;
        end
        zc$60$first = zfirst;
        zc$60$nz = interp$px[60];
        zc$60$oz = ozr$60$q[32'h0];
        if (zwin) begin
            ozr$60$d = ozr$60$q >> 32'h1;
            nzr$60$d = nzr$60$q >> 32'h1;
            if (interp$px[60]) begin
                nzr$60$d = (nzr$60$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$60$d = rr$60$q >> 32'h1;
            if (interp$px[60]) begin
                rr$60$d = (rr$60$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$60$d = gr$60$q >> 32'h1;
            if (interp$px[60]) begin
                gr$60$d = (gr$60$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$60$d = br$60$q >> 32'h1;
            if (interp$px[60]) begin
                br$60$d = (br$60$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$60$d = mask[60] & zc$60$closer;
        end
        zc$61$first = zfirst;
        zc$61$nz = interp$px[61];
        zc$61$oz = ozr$61$q[32'h0];
        if (zwin) begin
            ozr$61$d = ozr$61$q >> 32'h1;
            nzr$61$d = nzr$61$q >> 32'h1;
            if (interp$px[61]) begin
                nzr$61$d = (nzr$61$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$61$d = rr$61$q >> 32'h1;
            if (interp$px[61]) begin
                rr$61$d = (rr$61$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$61$d = gr$61$q >> 32'h1;
            if (interp$px[61]) begin
                gr$61$d = (gr$61$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$61$d = br$61$q >> 32'h1;
            if (interp$px[61]) begin
                br$61$d = (br$61$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$61$d = mask[61] & zc$61$closer;
        end
        zc$62$first = zfirst;
        zc$62$nz = interp$px[62];
        zc$62$oz = ozr$62$q[32'h0];
        if (zwin) begin
            ozr$62$d = ozr$62$q >> 32'h1;
            nzr$62$d = nzr$62$q >> 32'h1;
            if (interp$px[62]) begin
                nzr$62$d = (nzr$62$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$62$d = rr$62$q >> 32'h1;
            if (interp$px[62]) begin
                rr$62$d = (rr$62$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$62$d = gr$62$q >> 32'h1;
            if (interp$px[62]) begin
                gr$62$d = (gr$62$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$62$d = br$62$q >> 32'h1;
            if (interp$px[62]) begin
                br$62$d = (br$62$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$62$d = mask[62] & zc$62$closer;
        end
        zc$63$first = zfirst;
        zc$63$nz = interp$px[63];
        zc$63$oz = ozr$63$q[32'h0];
        if (zwin) begin
            ozr$63$d = ozr$63$q >> 32'h1;
            nzr$63$d = nzr$63$q >> 32'h1;
            if (interp$px[63]) begin
                nzr$63$d = (nzr$63$q >> 32'h1) | k_zmsb;
            end
        end
        if (rwin) begin
            rr$63$d = rr$63$q >> 32'h1;
            if (interp$px[63]) begin
                rr$63$d = (rr$63$q >> 32'h1) | k_cmsb;
            end
        end
        if (gwin) begin
            gr$63$d = gr$63$q >> 32'h1;
            if (interp$px[63]) begin
                gr$63$d = (gr$63$q >> 32'h1) | k_cmsb;
            end
        end
        if (bwin) begin
            br$63$d = br$63$q >> 32'h1;
            if (interp$px[63]) begin
                br$63$d = (br$63$q >> 32'h1) | k_cmsb;
            end
        end
        if (welatch) begin
            wes$63$d = mask[63] & zc$63$closer;
        end
        if (ozload) begin
            ozr$0$d = ozr$4$q;
            ozr$1$d = ozr$5$q;
            ozr$2$d = ozr$6$q;
            ozr$3$d = ozr$7$q;
            ozr$4$d = ozr$8$q;
            ozr$5$d = ozr$9$q;
            ozr$6$d = ozr$10$q;
            ozr$7$d = ozr$11$q;
            ozr$8$d = ozr$12$q;
            ozr$9$d = ozr$13$q;
            ozr$10$d = ozr$14$q;
            ozr$11$d = ozr$15$q;
            ozr$12$d = ozr$16$q;
            ozr$13$d = ozr$17$q;
            ozr$14$d = ozr$18$q;
            ozr$15$d = ozr$19$q;
            ozr$16$d = ozr$20$q;
            ozr$17$d = ozr$21$q;
            ozr$18$d = ozr$22$q;
            ozr$19$d = ozr$23$q;
            ozr$20$d = ozr$24$q;
            ozr$21$d = ozr$25$q;
            ozr$22$d = ozr$26$q;
            ozr$23$d = ozr$27$q;
            ozr$24$d = ozr$28$q;
            ozr$25$d = ozr$29$q;
            ozr$26$d = ozr$30$q;
            ozr$27$d = ozr$31$q;
            ozr$28$d = ozr$32$q;
            ozr$29$d = ozr$33$q;
            ozr$30$d = ozr$34$q;
            ozr$31$d = ozr$35$q;
            ozr$32$d = ozr$36$q;
            ozr$33$d = ozr$37$q;
            ozr$34$d = ozr$38$q;
            ozr$35$d = ozr$39$q;
            ozr$36$d = ozr$40$q;
            ozr$37$d = ozr$41$q;
            ozr$38$d = ozr$42$q;
            ozr$39$d = ozr$43$q;
            ozr$40$d = ozr$44$q;
            ozr$41$d = ozr$45$q;
            ozr$42$d = ozr$46$q;
            ozr$43$d = ozr$47$q;
            ozr$44$d = ozr$48$q;
            ozr$45$d = ozr$49$q;
            ozr$46$d = ozr$50$q;
            ozr$47$d = ozr$51$q;
            ozr$48$d = ozr$52$q;
            ozr$49$d = ozr$53$q;
            ozr$50$d = ozr$54$q;
            ozr$51$d = ozr$55$q;
            ozr$52$d = ozr$56$q;
            ozr$53$d = ozr$57$q;
            ozr$54$d = ozr$58$q;
            ozr$55$d = ozr$59$q;
            ozr$56$d = ozr$60$q;
            ozr$57$d = ozr$61$q;
            ozr$58$d = ozr$62$q;
            ozr$59$d = ozr$63$q;
            ozr$60$d = oz0;
            ozr$61$d = oz1;
            ozr$62$d = oz2;
            ozr$63$d = oz3;
        end
        dump = dc$q != 32'h0;
        dc$d = dc$q + 32'h1;
        if ((dc$q == 32'h0) | (dc$q == k_dq)) begin
            dc$d = 32'h0;
        end
        if (dstart) begin
            dc$d = 32'h1;
        end
        if (dump) begin
            nzr$0$d = nzr$4$q;
            rr$0$d = rr$4$q;
            gr$0$d = gr$4$q;
            br$0$d = br$4$q;
            wes$0$d = wes$4$q;
            nzr$1$d = nzr$5$q;
            rr$1$d = rr$5$q;
            gr$1$d = gr$5$q;
            br$1$d = br$5$q;
            wes$1$d = wes$5$q;
            nzr$2$d = nzr$6$q;
            rr$2$d = rr$6$q;
            gr$2$d = gr$6$q;
            br$2$d = br$6$q;
            wes$2$d = wes$6$q;
            nzr$3$d = nzr$7$q;
            rr$3$d = rr$7$q;
            gr$3$d = gr$7$q;
            br$3$d = br$7$q;
            wes$3$d = wes$7$q;
            nzr$4$d = nzr$8$q;
            rr$4$d = rr$8$q;
            gr$4$d = gr$8$q;
            br$4$d = br$8$q;
            wes$4$d = wes$8$q;
            nzr$5$d = nzr$9$q;
            rr$5$d = rr$9$q;
            gr$5$d = gr$9$q;
            br$5$d = br$9$q;
            wes$5$d = wes$9$q;
            nzr$6$d = nzr$10$q;
            rr$6$d = rr$10$q;
            gr$6$d = gr$10$q;
            br$6$d = br$10$q;
            wes$6$d = wes$10$q;
            nzr$7$d = nzr$11$q;
            rr$7$d = rr$11$q;
            gr$7$d = gr$11$q;
            br$7$d = br$11$q;
            wes$7$d = wes$11$q;
            nzr$8$d = nzr$12$q;
            rr$8$d = rr$12$q;
            gr$8$d = gr$12$q;
            br$8$d = br$12$q;
            wes$8$d = wes$12$q;
            nzr$9$d = nzr$13$q;
            rr$9$d = rr$13$q;
            gr$9$d = gr$13$q;
            br$9$d = br$13$q;
            wes$9$d = wes$13$q;
            nzr$10$d = nzr$14$q;
            rr$10$d = rr$14$q;
            gr$10$d = gr$14$q;
            br$10$d = br$14$q;
            wes$10$d = wes$14$q;
            nzr$11$d = nzr$15$q;
            rr$11$d = rr$15$q;
            gr$11$d = gr$15$q;
            br$11$d = br$15$q;
            wes$11$d = wes$15$q;
            nzr$12$d = nzr$16$q;
            rr$12$d = rr$16$q;
            gr$12$d = gr$16$q;
            br$12$d = br$16$q;
            wes$12$d = wes$16$q;
            nzr$13$d = nzr$17$q;
            rr$13$d = rr$17$q;
            gr$13$d = gr$17$q;
            br$13$d = br$17$q;
            wes$13$d = wes$17$q;
            nzr$14$d = nzr$18$q;
            rr$14$d = rr$18$q;
            gr$14$d = gr$18$q;
            br$14$d = br$18$q;
            wes$14$d = wes$18$q;
            nzr$15$d = nzr$19$q;
            rr$15$d = rr$19$q;
            gr$15$d = gr$19$q;
            br$15$d = br$19$q;
            wes$15$d = wes$19$q;
            nzr$16$d = nzr$20$q;
            rr$16$d = rr$20$q;
            gr$16$d = gr$20$q;
            br$16$d = br$20$q;
            wes$16$d = wes$20$q;
            nzr$17$d = nzr$21$q;
            rr$17$d = rr$21$q;
            gr$17$d = gr$21$q;
            br$17$d = br$21$q;
            wes$17$d = wes$21$q;
            nzr$18$d = nzr$22$q;
            rr$18$d = rr$22$q;
            gr$18$d = gr$22$q;
            br$18$d = br$22$q;
            wes$18$d = wes$22$q;
            nzr$19$d = nzr$23$q;
            rr$19$d = rr$23$q;
            gr$19$d = gr$23$q;
            br$19$d = br$23$q;
            wes$19$d = wes$23$q;
            nzr$20$d = nzr$24$q;
            rr$20$d = rr$24$q;
            gr$20$d = gr$24$q;
            br$20$d = br$24$q;
            wes$20$d = wes$24$q;
            nzr$21$d = nzr$25$q;
            rr$21$d = rr$25$q;
            gr$21$d = gr$25$q;
            br$21$d = br$25$q;
            wes$21$d = wes$25$q;
            nzr$22$d = nzr$26$q;
            rr$22$d = rr$26$q;
            gr$22$d = gr$26$q;
            br$22$d = br$26$q;
            wes$22$d = wes$26$q;
            nzr$23$d = nzr$27$q;
            rr$23$d = rr$27$q;
            gr$23$d = gr$27$q;
            br$23$d = br$27$q;
            wes$23$d = wes$27$q;
            nzr$24$d = nzr$28$q;
            rr$24$d = rr$28$q;
            gr$24$d = gr$28$q;
            br$24$d = br$28$q;
            wes$24$d = wes$28$q;
            nzr$25$d = nzr$29$q;
            rr$25$d = rr$29$q;
            gr$25$d = gr$29$q;
            br$25$d = br$29$q;
            wes$25$d = wes$29$q;
            nzr$26$d = nzr$30$q;
            rr$26$d = rr$30$q;
            gr$26$d = gr$30$q;
            br$26$d = br$30$q;
            wes$26$d = wes$30$q;
            nzr$27$d = nzr$31$q;
            rr$27$d = rr$31$q;
            gr$27$d = gr$31$q;
            br$27$d = br$31$q;
            wes$27$d = wes$31$q;
            nzr$28$d = nzr$32$q;
            rr$28$d = rr$32$q;
            gr$28$d = gr$32$q;
            br$28$d = br$32$q;
            wes$28$d = wes$32$q;
            nzr$29$d = nzr$33$q;
            rr$29$d = rr$33$q;
            gr$29$d = gr$33$q;
            br$29$d = br$33$q;
            wes$29$d = wes$33$q;
            nzr$30$d = nzr$34$q;
            rr$30$d = rr$34$q;
            gr$30$d = gr$34$q;
            br$30$d = br$34$q;
            wes$30$d = wes$34$q;
            nzr$31$d = nzr$35$q;
            rr$31$d = rr$35$q;
            gr$31$d = gr$35$q;
            br$31$d = br$35$q;
            wes$31$d = wes$35$q;
            nzr$32$d = nzr$36$q;
            rr$32$d = rr$36$q;
            gr$32$d = gr$36$q;
            br$32$d = br$36$q;
            wes$32$d = wes$36$q;
            nzr$33$d = nzr$37$q;
            rr$33$d = rr$37$q;
            gr$33$d = gr$37$q;
            br$33$d = br$37$q;
            wes$33$d = wes$37$q;
            nzr$34$d = nzr$38$q;
            rr$34$d = rr$38$q;
            gr$34$d = gr$38$q;
            br$34$d = br$38$q;
            wes$34$d = wes$38$q;
            nzr$35$d = nzr$39$q;
            rr$35$d = rr$39$q;
            gr$35$d = gr$39$q;
            br$35$d = br$39$q;
            wes$35$d = wes$39$q;
            nzr$36$d = nzr$40$q;
            rr$36$d = rr$40$q;
            gr$36$d = gr$40$q;
            br$36$d = br$40$q;
            wes$36$d = wes$40$q;
            nzr$37$d = nzr$41$q;
            rr$37$d = rr$41$q;
            gr$37$d = gr$41$q;
            br$37$d = br$41$q;
            wes$37$d = wes$41$q;
            nzr$38$d = nzr$42$q;
            rr$38$d = rr$42$q;
            gr$38$d = gr$42$q;
            br$38$d = br$42$q;
            wes$38$d = wes$42$q;
            nzr$39$d = nzr$43$q;
            rr$39$d = rr$43$q;
            gr$39$d = gr$43$q;
            br$39$d = br$43$q;
            wes$39$d = wes$43$q;
            nzr$40$d = nzr$44$q;
            rr$40$d = rr$44$q;
            gr$40$d = gr$44$q;
            br$40$d = br$44$q;
            wes$40$d = wes$44$q;
            nzr$41$d = nzr$45$q;
            rr$41$d = rr$45$q;
            gr$41$d = gr$45$q;
            br$41$d = br$45$q;
            wes$41$d = wes$45$q;
            nzr$42$d = nzr$46$q;
            rr$42$d = rr$46$q;
            gr$42$d = gr$46$q;
            br$42$d = br$46$q;
            wes$42$d = wes$46$q;
            nzr$43$d = nzr$47$q;
            rr$43$d = rr$47$q;
            gr$43$d = gr$47$q;
            br$43$d = br$47$q;
            wes$43$d = wes$47$q;
            nzr$44$d = nzr$48$q;
            rr$44$d = rr$48$q;
            gr$44$d = gr$48$q;
            br$44$d = br$48$q;
            wes$44$d = wes$48$q;
            nzr$45$d = nzr$49$q;
            rr$45$d = rr$49$q;
            gr$45$d = gr$49$q;
            br$45$d = br$49$q;
            wes$45$d = wes$49$q;
            nzr$46$d = nzr$50$q;
            rr$46$d = rr$50$q;
            gr$46$d = gr$50$q;
            br$46$d = br$50$q;
            wes$46$d = wes$50$q;
            nzr$47$d = nzr$51$q;
            rr$47$d = rr$51$q;
            gr$47$d = gr$51$q;
            br$47$d = br$51$q;
            wes$47$d = wes$51$q;
            nzr$48$d = nzr$52$q;
            rr$48$d = rr$52$q;
            gr$48$d = gr$52$q;
            br$48$d = br$52$q;
            wes$48$d = wes$52$q;
            nzr$49$d = nzr$53$q;
            rr$49$d = rr$53$q;
            gr$49$d = gr$53$q;
            br$49$d = br$53$q;
            wes$49$d = wes$53$q;
            nzr$50$d = nzr$54$q;
            rr$50$d = rr$54$q;
            gr$50$d = gr$54$q;
            br$50$d = br$54$q;
            wes$50$d = wes$54$q;
            nzr$51$d = nzr$55$q;
            rr$51$d = rr$55$q;
            gr$51$d = gr$55$q;
            br$51$d = br$55$q;
            wes$51$d = wes$55$q;
            nzr$52$d = nzr$56$q;
            rr$52$d = rr$56$q;
            gr$52$d = gr$56$q;
            br$52$d = br$56$q;
            wes$52$d = wes$56$q;
            nzr$53$d = nzr$57$q;
            rr$53$d = rr$57$q;
            gr$53$d = gr$57$q;
            br$53$d = br$57$q;
            wes$53$d = wes$57$q;
            nzr$54$d = nzr$58$q;
            rr$54$d = rr$58$q;
            gr$54$d = gr$58$q;
            br$54$d = br$58$q;
            wes$54$d = wes$58$q;
            nzr$55$d = nzr$59$q;
            rr$55$d = rr$59$q;
            gr$55$d = gr$59$q;
            br$55$d = br$59$q;
            wes$55$d = wes$59$q;
            nzr$56$d = nzr$60$q;
            rr$56$d = rr$60$q;
            gr$56$d = gr$60$q;
            br$56$d = br$60$q;
            wes$56$d = wes$60$q;
            nzr$57$d = nzr$61$q;
            rr$57$d = rr$61$q;
            gr$57$d = gr$61$q;
            br$57$d = br$61$q;
            wes$57$d = wes$61$q;
            nzr$58$d = nzr$62$q;
            rr$58$d = rr$62$q;
            gr$58$d = gr$62$q;
            br$58$d = br$62$q;
            wes$58$d = wes$62$q;
            nzr$59$d = nzr$63$q;
            rr$59$d = rr$63$q;
            gr$59$d = gr$63$q;
            br$59$d = br$63$q;
            wes$59$d = wes$63$q;
            nzr$60$d = 32'h0;
            rr$60$d = 32'h0;
            gr$60$d = 32'h0;
            br$60$d = 32'h0;
            wes$60$d = 1'b0;
            nzr$61$d = 32'h0;
            rr$61$d = 32'h0;
            gr$61$d = 32'h0;
            br$61$d = 32'h0;
            wes$61$d = 1'b0;
            nzr$62$d = 32'h0;
            rr$62$d = 32'h0;
            gr$62$d = 32'h0;
            br$62$d = 32'h0;
            wes$62$d = 1'b0;
            nzr$63$d = 32'h0;
            rr$63$d = 32'h0;
            gr$63$d = 32'h0;
            br$63$d = 32'h0;
            wes$63$d = 1'b0;
        end
        wr = dump;
        wr_addr = dc$q[(32'h0)+:(4)] - 32'h1;
        nz0 = nzr$0$q;
        nz1 = nzr$1$q;
        nz2 = nzr$2$q;
        nz3 = nzr$3$q;
        r0 = rr$0$q;
        r1 = rr$1$q;
        r2 = rr$2$q;
        r3 = rr$3$q;
        g0 = gr$0$q;
        g1 = gr$1$q;
        g2 = gr$2$q;
        g3 = gr$3$q;
        b0 = br$0$q;
        b1 = br$1$q;
        b2 = br$2$q;
        b3 = br$3$q;
        we0 = wes$0$q;
        we1 = wes$1$q;
        we2 = wes$2$q;
        we3 = wes$3$q;
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


module se$br$0(d,q,clock);
    
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
          
endmodule // se$br$0


module se$br$1(d,q,clock);
    
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
          
endmodule // se$br$1


module se$br$10(d,q,clock);
    
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
          
endmodule // se$br$10


module se$br$11(d,q,clock);
    
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
          
endmodule // se$br$11


module se$br$12(d,q,clock);
    
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
          
endmodule // se$br$12


module se$br$13(d,q,clock);
    
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
          
endmodule // se$br$13


module se$br$14(d,q,clock);
    
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
          
endmodule // se$br$14


module se$br$15(d,q,clock);
    
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
          
endmodule // se$br$15


module se$br$16(d,q,clock);
    
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
          
endmodule // se$br$16


module se$br$17(d,q,clock);
    
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
          
endmodule // se$br$17


module se$br$18(d,q,clock);
    
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
          
endmodule // se$br$18


module se$br$19(d,q,clock);
    
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
          
endmodule // se$br$19


module se$br$2(d,q,clock);
    
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
          
endmodule // se$br$2


module se$br$20(d,q,clock);
    
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
          
endmodule // se$br$20


module se$br$21(d,q,clock);
    
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
          
endmodule // se$br$21


module se$br$22(d,q,clock);
    
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
          
endmodule // se$br$22


module se$br$23(d,q,clock);
    
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
          
endmodule // se$br$23


module se$br$24(d,q,clock);
    
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
          
endmodule // se$br$24


module se$br$25(d,q,clock);
    
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
          
endmodule // se$br$25


module se$br$26(d,q,clock);
    
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
          
endmodule // se$br$26


module se$br$27(d,q,clock);
    
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
          
endmodule // se$br$27


module se$br$28(d,q,clock);
    
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
          
endmodule // se$br$28


module se$br$29(d,q,clock);
    
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
          
endmodule // se$br$29


module se$br$3(d,q,clock);
    
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
          
endmodule // se$br$3


module se$br$30(d,q,clock);
    
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
          
endmodule // se$br$30


module se$br$31(d,q,clock);
    
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
          
endmodule // se$br$31


module se$br$32(d,q,clock);
    
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
          
endmodule // se$br$32


module se$br$33(d,q,clock);
    
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
          
endmodule // se$br$33


module se$br$34(d,q,clock);
    
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
          
endmodule // se$br$34


module se$br$35(d,q,clock);
    
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
          
endmodule // se$br$35


module se$br$36(d,q,clock);
    
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
          
endmodule // se$br$36


module se$br$37(d,q,clock);
    
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
          
endmodule // se$br$37


module se$br$38(d,q,clock);
    
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
          
endmodule // se$br$38


module se$br$39(d,q,clock);
    
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
          
endmodule // se$br$39


module se$br$4(d,q,clock);
    
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
          
endmodule // se$br$4


module se$br$40(d,q,clock);
    
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
          
endmodule // se$br$40


module se$br$41(d,q,clock);
    
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
          
endmodule // se$br$41


module se$br$42(d,q,clock);
    
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
          
endmodule // se$br$42


module se$br$43(d,q,clock);
    
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
          
endmodule // se$br$43


module se$br$44(d,q,clock);
    
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
          
endmodule // se$br$44


module se$br$45(d,q,clock);
    
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
          
endmodule // se$br$45


module se$br$46(d,q,clock);
    
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
          
endmodule // se$br$46


module se$br$47(d,q,clock);
    
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
          
endmodule // se$br$47


module se$br$48(d,q,clock);
    
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
          
endmodule // se$br$48


module se$br$49(d,q,clock);
    
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
          
endmodule // se$br$49


module se$br$5(d,q,clock);
    
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
          
endmodule // se$br$5


module se$br$50(d,q,clock);
    
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
          
endmodule // se$br$50


module se$br$51(d,q,clock);
    
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
          
endmodule // se$br$51


module se$br$52(d,q,clock);
    
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
          
endmodule // se$br$52


module se$br$53(d,q,clock);
    
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
          
endmodule // se$br$53


module se$br$54(d,q,clock);
    
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
          
endmodule // se$br$54


module se$br$55(d,q,clock);
    
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
          
endmodule // se$br$55


module se$br$56(d,q,clock);
    
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
          
endmodule // se$br$56


module se$br$57(d,q,clock);
    
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
          
endmodule // se$br$57


module se$br$58(d,q,clock);
    
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
          
endmodule // se$br$58


module se$br$59(d,q,clock);
    
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
          
endmodule // se$br$59


module se$br$6(d,q,clock);
    
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
          
endmodule // se$br$6


module se$br$60(d,q,clock);
    
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
          
endmodule // se$br$60


module se$br$61(d,q,clock);
    
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
          
endmodule // se$br$61


module se$br$62(d,q,clock);
    
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
          
endmodule // se$br$62


module se$br$63(d,q,clock);
    
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
          
endmodule // se$br$63


module se$br$7(d,q,clock);
    
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
          
endmodule // se$br$7


module se$br$8(d,q,clock);
    
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
          
endmodule // se$br$8


module se$br$9(d,q,clock);
    
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
          
endmodule // se$br$9


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


module se$gr$0(d,q,clock);
    
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
          
endmodule // se$gr$0


module se$gr$1(d,q,clock);
    
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
          
endmodule // se$gr$1


module se$gr$10(d,q,clock);
    
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
          
endmodule // se$gr$10


module se$gr$11(d,q,clock);
    
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
          
endmodule // se$gr$11


module se$gr$12(d,q,clock);
    
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
          
endmodule // se$gr$12


module se$gr$13(d,q,clock);
    
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
          
endmodule // se$gr$13


module se$gr$14(d,q,clock);
    
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
          
endmodule // se$gr$14


module se$gr$15(d,q,clock);
    
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
          
endmodule // se$gr$15


module se$gr$16(d,q,clock);
    
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
          
endmodule // se$gr$16


module se$gr$17(d,q,clock);
    
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
          
endmodule // se$gr$17


module se$gr$18(d,q,clock);
    
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
          
endmodule // se$gr$18


module se$gr$19(d,q,clock);
    
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
          
endmodule // se$gr$19


module se$gr$2(d,q,clock);
    
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
          
endmodule // se$gr$2


module se$gr$20(d,q,clock);
    
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
          
endmodule // se$gr$20


module se$gr$21(d,q,clock);
    
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
          
endmodule // se$gr$21


module se$gr$22(d,q,clock);
    
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
          
endmodule // se$gr$22


module se$gr$23(d,q,clock);
    
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
          
endmodule // se$gr$23


module se$gr$24(d,q,clock);
    
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
          
endmodule // se$gr$24


module se$gr$25(d,q,clock);
    
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
          
endmodule // se$gr$25


module se$gr$26(d,q,clock);
    
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
          
endmodule // se$gr$26


module se$gr$27(d,q,clock);
    
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
          
endmodule // se$gr$27


module se$gr$28(d,q,clock);
    
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
          
endmodule // se$gr$28


module se$gr$29(d,q,clock);
    
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
          
endmodule // se$gr$29


module se$gr$3(d,q,clock);
    
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
          
endmodule // se$gr$3


module se$gr$30(d,q,clock);
    
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
          
endmodule // se$gr$30


module se$gr$31(d,q,clock);
    
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
          
endmodule // se$gr$31


module se$gr$32(d,q,clock);
    
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
          
endmodule // se$gr$32


module se$gr$33(d,q,clock);
    
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
          
endmodule // se$gr$33


module se$gr$34(d,q,clock);
    
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
          
endmodule // se$gr$34


module se$gr$35(d,q,clock);
    
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
          
endmodule // se$gr$35


module se$gr$36(d,q,clock);
    
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
          
endmodule // se$gr$36


module se$gr$37(d,q,clock);
    
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
          
endmodule // se$gr$37


module se$gr$38(d,q,clock);
    
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
          
endmodule // se$gr$38


module se$gr$39(d,q,clock);
    
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
          
endmodule // se$gr$39


module se$gr$4(d,q,clock);
    
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
          
endmodule // se$gr$4


module se$gr$40(d,q,clock);
    
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
          
endmodule // se$gr$40


module se$gr$41(d,q,clock);
    
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
          
endmodule // se$gr$41


module se$gr$42(d,q,clock);
    
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
          
endmodule // se$gr$42


module se$gr$43(d,q,clock);
    
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
          
endmodule // se$gr$43


module se$gr$44(d,q,clock);
    
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
          
endmodule // se$gr$44


module se$gr$45(d,q,clock);
    
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
          
endmodule // se$gr$45


module se$gr$46(d,q,clock);
    
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
          
endmodule // se$gr$46


module se$gr$47(d,q,clock);
    
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
          
endmodule // se$gr$47


module se$gr$48(d,q,clock);
    
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
          
endmodule // se$gr$48


module se$gr$49(d,q,clock);
    
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
          
endmodule // se$gr$49


module se$gr$5(d,q,clock);
    
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
          
endmodule // se$gr$5


module se$gr$50(d,q,clock);
    
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
          
endmodule // se$gr$50


module se$gr$51(d,q,clock);
    
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
          
endmodule // se$gr$51


module se$gr$52(d,q,clock);
    
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
          
endmodule // se$gr$52


module se$gr$53(d,q,clock);
    
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
          
endmodule // se$gr$53


module se$gr$54(d,q,clock);
    
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
          
endmodule // se$gr$54


module se$gr$55(d,q,clock);
    
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
          
endmodule // se$gr$55


module se$gr$56(d,q,clock);
    
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
          
endmodule // se$gr$56


module se$gr$57(d,q,clock);
    
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
          
endmodule // se$gr$57


module se$gr$58(d,q,clock);
    
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
          
endmodule // se$gr$58


module se$gr$59(d,q,clock);
    
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
          
endmodule // se$gr$59


module se$gr$6(d,q,clock);
    
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
          
endmodule // se$gr$6


module se$gr$60(d,q,clock);
    
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
          
endmodule // se$gr$60


module se$gr$61(d,q,clock);
    
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
          
endmodule // se$gr$61


module se$gr$62(d,q,clock);
    
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
          
endmodule // se$gr$62


module se$gr$63(d,q,clock);
    
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
          
endmodule // se$gr$63


module se$gr$7(d,q,clock);
    
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
          
endmodule // se$gr$7


module se$gr$8(d,q,clock);
    
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
          
endmodule // se$gr$8


module se$gr$9(d,q,clock);
    
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
          
endmodule // se$gr$9


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


module se$nzr$0(d,q,clock);
    
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
          
endmodule // se$nzr$0


module se$nzr$1(d,q,clock);
    
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
          
endmodule // se$nzr$1


module se$nzr$10(d,q,clock);
    
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
          
endmodule // se$nzr$10


module se$nzr$11(d,q,clock);
    
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
          
endmodule // se$nzr$11


module se$nzr$12(d,q,clock);
    
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
          
endmodule // se$nzr$12


module se$nzr$13(d,q,clock);
    
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
          
endmodule // se$nzr$13


module se$nzr$14(d,q,clock);
    
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
          
endmodule // se$nzr$14


module se$nzr$15(d,q,clock);
    
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
          
endmodule // se$nzr$15


module se$nzr$16(d,q,clock);
    
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
          
endmodule // se$nzr$16


module se$nzr$17(d,q,clock);
    
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
          
endmodule // se$nzr$17


module se$nzr$18(d,q,clock);
    
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
          
endmodule // se$nzr$18


module se$nzr$19(d,q,clock);
    
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
          
endmodule // se$nzr$19


module se$nzr$2(d,q,clock);
    
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
          
endmodule // se$nzr$2


module se$nzr$20(d,q,clock);
    
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
          
endmodule // se$nzr$20


module se$nzr$21(d,q,clock);
    
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
          
endmodule // se$nzr$21


module se$nzr$22(d,q,clock);
    
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
          
endmodule // se$nzr$22


module se$nzr$23(d,q,clock);
    
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
          
endmodule // se$nzr$23


module se$nzr$24(d,q,clock);
    
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
          
endmodule // se$nzr$24


module se$nzr$25(d,q,clock);
    
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
          
endmodule // se$nzr$25


module se$nzr$26(d,q,clock);
    
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
          
endmodule // se$nzr$26


module se$nzr$27(d,q,clock);
    
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
          
endmodule // se$nzr$27


module se$nzr$28(d,q,clock);
    
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
          
endmodule // se$nzr$28


module se$nzr$29(d,q,clock);
    
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
          
endmodule // se$nzr$29


module se$nzr$3(d,q,clock);
    
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
          
endmodule // se$nzr$3


module se$nzr$30(d,q,clock);
    
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
          
endmodule // se$nzr$30


module se$nzr$31(d,q,clock);
    
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
          
endmodule // se$nzr$31


module se$nzr$32(d,q,clock);
    
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
          
endmodule // se$nzr$32


module se$nzr$33(d,q,clock);
    
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
          
endmodule // se$nzr$33


module se$nzr$34(d,q,clock);
    
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
          
endmodule // se$nzr$34


module se$nzr$35(d,q,clock);
    
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
          
endmodule // se$nzr$35


module se$nzr$36(d,q,clock);
    
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
          
endmodule // se$nzr$36


module se$nzr$37(d,q,clock);
    
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
          
endmodule // se$nzr$37


module se$nzr$38(d,q,clock);
    
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
          
endmodule // se$nzr$38


module se$nzr$39(d,q,clock);
    
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
          
endmodule // se$nzr$39


module se$nzr$4(d,q,clock);
    
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
          
endmodule // se$nzr$4


module se$nzr$40(d,q,clock);
    
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
          
endmodule // se$nzr$40


module se$nzr$41(d,q,clock);
    
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
          
endmodule // se$nzr$41


module se$nzr$42(d,q,clock);
    
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
          
endmodule // se$nzr$42


module se$nzr$43(d,q,clock);
    
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
          
endmodule // se$nzr$43


module se$nzr$44(d,q,clock);
    
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
          
endmodule // se$nzr$44


module se$nzr$45(d,q,clock);
    
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
          
endmodule // se$nzr$45


module se$nzr$46(d,q,clock);
    
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
          
endmodule // se$nzr$46


module se$nzr$47(d,q,clock);
    
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
          
endmodule // se$nzr$47


module se$nzr$48(d,q,clock);
    
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
          
endmodule // se$nzr$48


module se$nzr$49(d,q,clock);
    
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
          
endmodule // se$nzr$49


module se$nzr$5(d,q,clock);
    
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
          
endmodule // se$nzr$5


module se$nzr$50(d,q,clock);
    
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
          
endmodule // se$nzr$50


module se$nzr$51(d,q,clock);
    
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
          
endmodule // se$nzr$51


module se$nzr$52(d,q,clock);
    
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
          
endmodule // se$nzr$52


module se$nzr$53(d,q,clock);
    
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
          
endmodule // se$nzr$53


module se$nzr$54(d,q,clock);
    
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
          
endmodule // se$nzr$54


module se$nzr$55(d,q,clock);
    
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
          
endmodule // se$nzr$55


module se$nzr$56(d,q,clock);
    
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
          
endmodule // se$nzr$56


module se$nzr$57(d,q,clock);
    
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
          
endmodule // se$nzr$57


module se$nzr$58(d,q,clock);
    
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
          
endmodule // se$nzr$58


module se$nzr$59(d,q,clock);
    
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
          
endmodule // se$nzr$59


module se$nzr$6(d,q,clock);
    
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
          
endmodule // se$nzr$6


module se$nzr$60(d,q,clock);
    
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
          
endmodule // se$nzr$60


module se$nzr$61(d,q,clock);
    
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
          
endmodule // se$nzr$61


module se$nzr$62(d,q,clock);
    
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
          
endmodule // se$nzr$62


module se$nzr$63(d,q,clock);
    
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
          
endmodule // se$nzr$63


module se$nzr$7(d,q,clock);
    
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
          
endmodule // se$nzr$7


module se$nzr$8(d,q,clock);
    
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
          
endmodule // se$nzr$8


module se$nzr$9(d,q,clock);
    
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
          
endmodule // se$nzr$9


module se$ozr$0(d,q,clock);
    
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
          
endmodule // se$ozr$0


module se$ozr$1(d,q,clock);
    
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
          
endmodule // se$ozr$1


module se$ozr$10(d,q,clock);
    
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
          
endmodule // se$ozr$10


module se$ozr$11(d,q,clock);
    
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
          
endmodule // se$ozr$11


module se$ozr$12(d,q,clock);
    
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
          
endmodule // se$ozr$12


module se$ozr$13(d,q,clock);
    
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
          
endmodule // se$ozr$13


module se$ozr$14(d,q,clock);
    
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
          
endmodule // se$ozr$14


module se$ozr$15(d,q,clock);
    
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
          
endmodule // se$ozr$15


module se$ozr$16(d,q,clock);
    
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
          
endmodule // se$ozr$16


module se$ozr$17(d,q,clock);
    
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
          
endmodule // se$ozr$17


module se$ozr$18(d,q,clock);
    
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
          
endmodule // se$ozr$18


module se$ozr$19(d,q,clock);
    
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
          
endmodule // se$ozr$19


module se$ozr$2(d,q,clock);
    
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
          
endmodule // se$ozr$2


module se$ozr$20(d,q,clock);
    
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
          
endmodule // se$ozr$20


module se$ozr$21(d,q,clock);
    
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
          
endmodule // se$ozr$21


module se$ozr$22(d,q,clock);
    
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
          
endmodule // se$ozr$22


module se$ozr$23(d,q,clock);
    
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
          
endmodule // se$ozr$23


module se$ozr$24(d,q,clock);
    
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
          
endmodule // se$ozr$24


module se$ozr$25(d,q,clock);
    
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
          
endmodule // se$ozr$25


module se$ozr$26(d,q,clock);
    
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
          
endmodule // se$ozr$26


module se$ozr$27(d,q,clock);
    
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
          
endmodule // se$ozr$27


module se$ozr$28(d,q,clock);
    
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
          
endmodule // se$ozr$28


module se$ozr$29(d,q,clock);
    
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
          
endmodule // se$ozr$29


module se$ozr$3(d,q,clock);
    
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
          
endmodule // se$ozr$3


module se$ozr$30(d,q,clock);
    
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
          
endmodule // se$ozr$30


module se$ozr$31(d,q,clock);
    
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
          
endmodule // se$ozr$31


module se$ozr$32(d,q,clock);
    
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
          
endmodule // se$ozr$32


module se$ozr$33(d,q,clock);
    
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
          
endmodule // se$ozr$33


module se$ozr$34(d,q,clock);
    
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
          
endmodule // se$ozr$34


module se$ozr$35(d,q,clock);
    
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
          
endmodule // se$ozr$35


module se$ozr$36(d,q,clock);
    
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
          
endmodule // se$ozr$36


module se$ozr$37(d,q,clock);
    
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
          
endmodule // se$ozr$37


module se$ozr$38(d,q,clock);
    
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
          
endmodule // se$ozr$38


module se$ozr$39(d,q,clock);
    
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
          
endmodule // se$ozr$39


module se$ozr$4(d,q,clock);
    
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
          
endmodule // se$ozr$4


module se$ozr$40(d,q,clock);
    
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
          
endmodule // se$ozr$40


module se$ozr$41(d,q,clock);
    
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
          
endmodule // se$ozr$41


module se$ozr$42(d,q,clock);
    
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
          
endmodule // se$ozr$42


module se$ozr$43(d,q,clock);
    
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
          
endmodule // se$ozr$43


module se$ozr$44(d,q,clock);
    
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
          
endmodule // se$ozr$44


module se$ozr$45(d,q,clock);
    
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
          
endmodule // se$ozr$45


module se$ozr$46(d,q,clock);
    
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
          
endmodule // se$ozr$46


module se$ozr$47(d,q,clock);
    
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
          
endmodule // se$ozr$47


module se$ozr$48(d,q,clock);
    
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
          
endmodule // se$ozr$48


module se$ozr$49(d,q,clock);
    
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
          
endmodule // se$ozr$49


module se$ozr$5(d,q,clock);
    
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
          
endmodule // se$ozr$5


module se$ozr$50(d,q,clock);
    
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
          
endmodule // se$ozr$50


module se$ozr$51(d,q,clock);
    
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
          
endmodule // se$ozr$51


module se$ozr$52(d,q,clock);
    
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
          
endmodule // se$ozr$52


module se$ozr$53(d,q,clock);
    
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
          
endmodule // se$ozr$53


module se$ozr$54(d,q,clock);
    
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
          
endmodule // se$ozr$54


module se$ozr$55(d,q,clock);
    
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
          
endmodule // se$ozr$55


module se$ozr$56(d,q,clock);
    
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
          
endmodule // se$ozr$56


module se$ozr$57(d,q,clock);
    
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
          
endmodule // se$ozr$57


module se$ozr$58(d,q,clock);
    
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
          
endmodule // se$ozr$58


module se$ozr$59(d,q,clock);
    
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
          
endmodule // se$ozr$59


module se$ozr$6(d,q,clock);
    
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
          
endmodule // se$ozr$6


module se$ozr$60(d,q,clock);
    
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
          
endmodule // se$ozr$60


module se$ozr$61(d,q,clock);
    
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
          
endmodule // se$ozr$61


module se$ozr$62(d,q,clock);
    
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
          
endmodule // se$ozr$62


module se$ozr$63(d,q,clock);
    
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
          
endmodule // se$ozr$63


module se$ozr$7(d,q,clock);
    
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
          
endmodule // se$ozr$7


module se$ozr$8(d,q,clock);
    
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
          
endmodule // se$ozr$8


module se$ozr$9(d,q,clock);
    
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
          
endmodule // se$ozr$9


module se$rr$0(d,q,clock);
    
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
          
endmodule // se$rr$0


module se$rr$1(d,q,clock);
    
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
          
endmodule // se$rr$1


module se$rr$10(d,q,clock);
    
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
          
endmodule // se$rr$10


module se$rr$11(d,q,clock);
    
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
          
endmodule // se$rr$11


module se$rr$12(d,q,clock);
    
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
          
endmodule // se$rr$12


module se$rr$13(d,q,clock);
    
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
          
endmodule // se$rr$13


module se$rr$14(d,q,clock);
    
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
          
endmodule // se$rr$14


module se$rr$15(d,q,clock);
    
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
          
endmodule // se$rr$15


module se$rr$16(d,q,clock);
    
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
          
endmodule // se$rr$16


module se$rr$17(d,q,clock);
    
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
          
endmodule // se$rr$17


module se$rr$18(d,q,clock);
    
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
          
endmodule // se$rr$18


module se$rr$19(d,q,clock);
    
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
          
endmodule // se$rr$19


module se$rr$2(d,q,clock);
    
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
          
endmodule // se$rr$2


module se$rr$20(d,q,clock);
    
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
          
endmodule // se$rr$20


module se$rr$21(d,q,clock);
    
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
          
endmodule // se$rr$21


module se$rr$22(d,q,clock);
    
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
          
endmodule // se$rr$22


module se$rr$23(d,q,clock);
    
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
          
endmodule // se$rr$23


module se$rr$24(d,q,clock);
    
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
          
endmodule // se$rr$24


module se$rr$25(d,q,clock);
    
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
          
endmodule // se$rr$25


module se$rr$26(d,q,clock);
    
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
          
endmodule // se$rr$26


module se$rr$27(d,q,clock);
    
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
          
endmodule // se$rr$27


module se$rr$28(d,q,clock);
    
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
          
endmodule // se$rr$28


module se$rr$29(d,q,clock);
    
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
          
endmodule // se$rr$29


module se$rr$3(d,q,clock);
    
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
          
endmodule // se$rr$3


module se$rr$30(d,q,clock);
    
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
          
endmodule // se$rr$30


module se$rr$31(d,q,clock);
    
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
          
endmodule // se$rr$31


module se$rr$32(d,q,clock);
    
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
          
endmodule // se$rr$32


module se$rr$33(d,q,clock);
    
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
          
endmodule // se$rr$33


module se$rr$34(d,q,clock);
    
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
          
endmodule // se$rr$34


module se$rr$35(d,q,clock);
    
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
          
endmodule // se$rr$35


module se$rr$36(d,q,clock);
    
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
          
endmodule // se$rr$36


module se$rr$37(d,q,clock);
    
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
          
endmodule // se$rr$37


module se$rr$38(d,q,clock);
    
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
          
endmodule // se$rr$38


module se$rr$39(d,q,clock);
    
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
          
endmodule // se$rr$39


module se$rr$4(d,q,clock);
    
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
          
endmodule // se$rr$4


module se$rr$40(d,q,clock);
    
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
          
endmodule // se$rr$40


module se$rr$41(d,q,clock);
    
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
          
endmodule // se$rr$41


module se$rr$42(d,q,clock);
    
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
          
endmodule // se$rr$42


module se$rr$43(d,q,clock);
    
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
          
endmodule // se$rr$43


module se$rr$44(d,q,clock);
    
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
          
endmodule // se$rr$44


module se$rr$45(d,q,clock);
    
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
          
endmodule // se$rr$45


module se$rr$46(d,q,clock);
    
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
          
endmodule // se$rr$46


module se$rr$47(d,q,clock);
    
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
          
endmodule // se$rr$47


module se$rr$48(d,q,clock);
    
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
          
endmodule // se$rr$48


module se$rr$49(d,q,clock);
    
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
          
endmodule // se$rr$49


module se$rr$5(d,q,clock);
    
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
          
endmodule // se$rr$5


module se$rr$50(d,q,clock);
    
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
          
endmodule // se$rr$50


module se$rr$51(d,q,clock);
    
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
          
endmodule // se$rr$51


module se$rr$52(d,q,clock);
    
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
          
endmodule // se$rr$52


module se$rr$53(d,q,clock);
    
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
          
endmodule // se$rr$53


module se$rr$54(d,q,clock);
    
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
          
endmodule // se$rr$54


module se$rr$55(d,q,clock);
    
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
          
endmodule // se$rr$55


module se$rr$56(d,q,clock);
    
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
          
endmodule // se$rr$56


module se$rr$57(d,q,clock);
    
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
          
endmodule // se$rr$57


module se$rr$58(d,q,clock);
    
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
          
endmodule // se$rr$58


module se$rr$59(d,q,clock);
    
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
          
endmodule // se$rr$59


module se$rr$6(d,q,clock);
    
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
          
endmodule // se$rr$6


module se$rr$60(d,q,clock);
    
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
          
endmodule // se$rr$60


module se$rr$61(d,q,clock);
    
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
          
endmodule // se$rr$61


module se$rr$62(d,q,clock);
    
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
          
endmodule // se$rr$62


module se$rr$63(d,q,clock);
    
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
          
endmodule // se$rr$63


module se$rr$7(d,q,clock);
    
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
          
endmodule // se$rr$7


module se$rr$8(d,q,clock);
    
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
          
endmodule // se$rr$8


module se$rr$9(d,q,clock);
    
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
          
endmodule // se$rr$9


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
