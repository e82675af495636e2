

module divider(clock,inp_valid,inp_ready,hold,inp_n,inp_d,out_valid,out_ready,out_q,out_r);
    
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
    divider$stages$0 stages$0(
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
    divider$stages$1 stages$1(
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
    divider$stages$2 stages$2(
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
    divider$stages$3 stages$3(
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
    divider$stages$4 stages$4(
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
    divider$stages$5 stages$5(
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
    divider$stages$6 stages$6(
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
    divider$stages$7 stages$7(
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
    divider$stages$8 stages$8(
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
    divider$stages$9 stages$9(
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
    divider$stages$10 stages$10(
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
    divider$stages$11 stages$11(
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
    divider$stages$12 stages$12(
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
    divider$stages$13 stages$13(
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
    divider$stages$14 stages$14(
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
    divider$stages$15 stages$15(
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
    divider$stages$16 stages$16(
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
    divider$stages$17 stages$17(
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
    divider$stages$18 stages$18(
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
    divider$stages$19 stages$19(
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
    divider$stages$20 stages$20(
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
    divider$stages$21 stages$21(
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
    divider$stages$22 stages$22(
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
    divider$stages$23 stages$23(
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
    divider$stages$24 stages$24(
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
    
endmodule // divider


module divider$stages$0(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
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
    divider$stages$0$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    divider$stages$0$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    divider$stages$0$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    divider$stages$0$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    divider$stages$0$neg_r neg_r(
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
    
endmodule // divider$stages$0


module divider$stages$0$d_r(d,q,clock);
    
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
          
endmodule // divider$stages$0$d_r


module divider$stages$0$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$0$neg_r


module divider$stages$0$p_r(d,q,clock);
    
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
          
endmodule // divider$stages$0$p_r


module divider$stages$0$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$0$valid_r


module divider$stages$0$x_r(d,q,clock);
    
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
          
endmodule // divider$stages$0$x_r


module divider$stages$1(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
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
    divider$stages$1$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    divider$stages$1$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    divider$stages$1$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    divider$stages$1$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    divider$stages$1$neg_r neg_r(
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
    
endmodule // divider$stages$1


module divider$stages$1$d_r(d,q,clock);
    
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
          
endmodule // divider$stages$1$d_r


module divider$stages$1$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$1$neg_r


module divider$stages$1$p_r(d,q,clock);
    
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
          
endmodule // divider$stages$1$p_r


module divider$stages$1$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$1$valid_r


module divider$stages$1$x_r(d,q,clock);
    
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
          
endmodule // divider$stages$1$x_r


module divider$stages$10(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
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
    divider$stages$10$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    divider$stages$10$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    divider$stages$10$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    divider$stages$10$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    divider$stages$10$neg_r neg_r(
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
    
endmodule // divider$stages$10


module divider$stages$10$d_r(d,q,clock);
    
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
          
endmodule // divider$stages$10$d_r


module divider$stages$10$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$10$neg_r


module divider$stages$10$p_r(d,q,clock);
    
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
          
endmodule // divider$stages$10$p_r


module divider$stages$10$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$10$valid_r


module divider$stages$10$x_r(d,q,clock);
    
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
          
endmodule // divider$stages$10$x_r


module divider$stages$11(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
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
    divider$stages$11$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    divider$stages$11$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    divider$stages$11$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    divider$stages$11$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    divider$stages$11$neg_r neg_r(
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
    
endmodule // divider$stages$11


module divider$stages$11$d_r(d,q,clock);
    
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
          
endmodule // divider$stages$11$d_r


module divider$stages$11$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$11$neg_r


module divider$stages$11$p_r(d,q,clock);
    
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
          
endmodule // divider$stages$11$p_r


module divider$stages$11$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$11$valid_r


module divider$stages$11$x_r(d,q,clock);
    
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
          
endmodule // divider$stages$11$x_r


module divider$stages$12(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
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
    divider$stages$12$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    divider$stages$12$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    divider$stages$12$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    divider$stages$12$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    divider$stages$12$neg_r neg_r(
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
    
endmodule // divider$stages$12


module divider$stages$12$d_r(d,q,clock);
    
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
          
endmodule // divider$stages$12$d_r


module divider$stages$12$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$12$neg_r


module divider$stages$12$p_r(d,q,clock);
    
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
          
endmodule // divider$stages$12$p_r


module divider$stages$12$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$12$valid_r


module divider$stages$12$x_r(d,q,clock);
    
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
          
endmodule // divider$stages$12$x_r


module divider$stages$13(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
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
    divider$stages$13$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    divider$stages$13$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    divider$stages$13$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    divider$stages$13$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    divider$stages$13$neg_r neg_r(
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
    
endmodule // divider$stages$13


module divider$stages$13$d_r(d,q,clock);
    
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
          
endmodule // divider$stages$13$d_r


module divider$stages$13$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$13$neg_r


module divider$stages$13$p_r(d,q,clock);
    
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
          
endmodule // divider$stages$13$p_r


module divider$stages$13$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$13$valid_r


module divider$stages$13$x_r(d,q,clock);
    
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
          
endmodule // divider$stages$13$x_r


module divider$stages$14(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
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
    divider$stages$14$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    divider$stages$14$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    divider$stages$14$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    divider$stages$14$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    divider$stages$14$neg_r neg_r(
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
    
endmodule // divider$stages$14


module divider$stages$14$d_r(d,q,clock);
    
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
          
endmodule // divider$stages$14$d_r


module divider$stages$14$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$14$neg_r


module divider$stages$14$p_r(d,q,clock);
    
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
          
endmodule // divider$stages$14$p_r


module divider$stages$14$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$14$valid_r


module divider$stages$14$x_r(d,q,clock);
    
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
          
endmodule // divider$stages$14$x_r


module divider$stages$15(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
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
    divider$stages$15$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    divider$stages$15$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    divider$stages$15$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    divider$stages$15$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    divider$stages$15$neg_r neg_r(
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
    
endmodule // divider$stages$15


module divider$stages$15$d_r(d,q,clock);
    
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
          
endmodule // divider$stages$15$d_r


module divider$stages$15$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$15$neg_r


module divider$stages$15$p_r(d,q,clock);
    
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
          
endmodule // divider$stages$15$p_r


module divider$stages$15$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$15$valid_r


module divider$stages$15$x_r(d,q,clock);
    
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
          
endmodule // divider$stages$15$x_r


module divider$stages$16(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
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
    divider$stages$16$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    divider$stages$16$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    divider$stages$16$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    divider$stages$16$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    divider$stages$16$neg_r neg_r(
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
    
endmodule // divider$stages$16


module divider$stages$16$d_r(d,q,clock);
    
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
          
endmodule // divider$stages$16$d_r


module divider$stages$16$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$16$neg_r


module divider$stages$16$p_r(d,q,clock);
    
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
          
endmodule // divider$stages$16$p_r


module divider$stages$16$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$16$valid_r


module divider$stages$16$x_r(d,q,clock);
    
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
          
endmodule // divider$stages$16$x_r


module divider$stages$17(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
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
    divider$stages$17$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    divider$stages$17$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    divider$stages$17$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    divider$stages$17$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    divider$stages$17$neg_r neg_r(
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
    
endmodule // divider$stages$17


module divider$stages$17$d_r(d,q,clock);
    
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
          
endmodule // divider$stages$17$d_r


module divider$stages$17$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$17$neg_r


module divider$stages$17$p_r(d,q,clock);
    
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
          
endmodule // divider$stages$17$p_r


module divider$stages$17$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$17$valid_r


module divider$stages$17$x_r(d,q,clock);
    
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
          
endmodule // divider$stages$17$x_r


module divider$stages$18(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
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
    divider$stages$18$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    divider$stages$18$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    divider$stages$18$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    divider$stages$18$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    divider$stages$18$neg_r neg_r(
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
    
endmodule // divider$stages$18


module divider$stages$18$d_r(d,q,clock);
    
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
          
endmodule // divider$stages$18$d_r


module divider$stages$18$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$18$neg_r


module divider$stages$18$p_r(d,q,clock);
    
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
          
endmodule // divider$stages$18$p_r


module divider$stages$18$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$18$valid_r


module divider$stages$18$x_r(d,q,clock);
    
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
          
endmodule // divider$stages$18$x_r


module divider$stages$19(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
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
    divider$stages$19$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    divider$stages$19$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    divider$stages$19$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    divider$stages$19$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    divider$stages$19$neg_r neg_r(
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
    
endmodule // divider$stages$19


module divider$stages$19$d_r(d,q,clock);
    
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
          
endmodule // divider$stages$19$d_r


module divider$stages$19$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$19$neg_r


module divider$stages$19$p_r(d,q,clock);
    
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
          
endmodule // divider$stages$19$p_r


module divider$stages$19$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$19$valid_r


module divider$stages$19$x_r(d,q,clock);
    
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
          
endmodule // divider$stages$19$x_r


module divider$stages$2(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
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
    divider$stages$2$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    divider$stages$2$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    divider$stages$2$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    divider$stages$2$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    divider$stages$2$neg_r neg_r(
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
    
endmodule // divider$stages$2


module divider$stages$2$d_r(d,q,clock);
    
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
          
endmodule // divider$stages$2$d_r


module divider$stages$2$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$2$neg_r


module divider$stages$2$p_r(d,q,clock);
    
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
          
endmodule // divider$stages$2$p_r


module divider$stages$2$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$2$valid_r


module divider$stages$2$x_r(d,q,clock);
    
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
          
endmodule // divider$stages$2$x_r


module divider$stages$20(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
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
    divider$stages$20$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    divider$stages$20$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    divider$stages$20$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    divider$stages$20$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    divider$stages$20$neg_r neg_r(
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
    
endmodule // divider$stages$20


module divider$stages$20$d_r(d,q,clock);
    
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
          
endmodule // divider$stages$20$d_r


module divider$stages$20$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$20$neg_r


module divider$stages$20$p_r(d,q,clock);
    
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
          
endmodule // divider$stages$20$p_r


module divider$stages$20$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$20$valid_r


module divider$stages$20$x_r(d,q,clock);
    
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
          
endmodule // divider$stages$20$x_r


module divider$stages$21(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
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
    divider$stages$21$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    divider$stages$21$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    divider$stages$21$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    divider$stages$21$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    divider$stages$21$neg_r neg_r(
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
    
endmodule // divider$stages$21


module divider$stages$21$d_r(d,q,clock);
    
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
          
endmodule // divider$stages$21$d_r


module divider$stages$21$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$21$neg_r


module divider$stages$21$p_r(d,q,clock);
    
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
          
endmodule // divider$stages$21$p_r


module divider$stages$21$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$21$valid_r


module divider$stages$21$x_r(d,q,clock);
    
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
          
endmodule // divider$stages$21$x_r


module divider$stages$22(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
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
    divider$stages$22$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    divider$stages$22$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    divider$stages$22$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    divider$stages$22$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    divider$stages$22$neg_r neg_r(
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
    
endmodule // divider$stages$22


module divider$stages$22$d_r(d,q,clock);
    
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
          
endmodule // divider$stages$22$d_r


module divider$stages$22$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$22$neg_r


module divider$stages$22$p_r(d,q,clock);
    
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
          
endmodule // divider$stages$22$p_r


module divider$stages$22$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$22$valid_r


module divider$stages$22$x_r(d,q,clock);
    
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
          
endmodule // divider$stages$22$x_r


module divider$stages$23(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
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
    divider$stages$23$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    divider$stages$23$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    divider$stages$23$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    divider$stages$23$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    divider$stages$23$neg_r neg_r(
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
    
endmodule // divider$stages$23


module divider$stages$23$d_r(d,q,clock);
    
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
          
endmodule // divider$stages$23$d_r


module divider$stages$23$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$23$neg_r


module divider$stages$23$p_r(d,q,clock);
    
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
          
endmodule // divider$stages$23$p_r


module divider$stages$23$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$23$valid_r


module divider$stages$23$x_r(d,q,clock);
    
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
          
endmodule // divider$stages$23$x_r


module divider$stages$24(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
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
    divider$stages$24$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    divider$stages$24$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    divider$stages$24$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    divider$stages$24$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    divider$stages$24$neg_r neg_r(
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
    
endmodule // divider$stages$24


module divider$stages$24$d_r(d,q,clock);
    
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
          
endmodule // divider$stages$24$d_r


module divider$stages$24$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$24$neg_r


module divider$stages$24$p_r(d,q,clock);
    
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
          
endmodule // divider$stages$24$p_r


module divider$stages$24$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$24$valid_r


module divider$stages$24$x_r(d,q,clock);
    
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
          
endmodule // divider$stages$24$x_r


module divider$stages$3(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
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
    divider$stages$3$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    divider$stages$3$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    divider$stages$3$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    divider$stages$3$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    divider$stages$3$neg_r neg_r(
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
    
endmodule // divider$stages$3


module divider$stages$3$d_r(d,q,clock);
    
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
          
endmodule // divider$stages$3$d_r


module divider$stages$3$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$3$neg_r


module divider$stages$3$p_r(d,q,clock);
    
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
          
endmodule // divider$stages$3$p_r


module divider$stages$3$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$3$valid_r


module divider$stages$3$x_r(d,q,clock);
    
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
          
endmodule // divider$stages$3$x_r


module divider$stages$4(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
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
    divider$stages$4$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    divider$stages$4$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    divider$stages$4$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    divider$stages$4$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    divider$stages$4$neg_r neg_r(
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
    
endmodule // divider$stages$4


module divider$stages$4$d_r(d,q,clock);
    
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
          
endmodule // divider$stages$4$d_r


module divider$stages$4$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$4$neg_r


module divider$stages$4$p_r(d,q,clock);
    
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
          
endmodule // divider$stages$4$p_r


module divider$stages$4$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$4$valid_r


module divider$stages$4$x_r(d,q,clock);
    
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
          
endmodule // divider$stages$4$x_r


module divider$stages$5(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
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
    divider$stages$5$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    divider$stages$5$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    divider$stages$5$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    divider$stages$5$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    divider$stages$5$neg_r neg_r(
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
    
endmodule // divider$stages$5


module divider$stages$5$d_r(d,q,clock);
    
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
          
endmodule // divider$stages$5$d_r


module divider$stages$5$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$5$neg_r


module divider$stages$5$p_r(d,q,clock);
    
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
          
endmodule // divider$stages$5$p_r


module divider$stages$5$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$5$valid_r


module divider$stages$5$x_r(d,q,clock);
    
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
          
endmodule // divider$stages$5$x_r


module divider$stages$6(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
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
    divider$stages$6$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    divider$stages$6$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    divider$stages$6$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    divider$stages$6$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    divider$stages$6$neg_r neg_r(
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
    
endmodule // divider$stages$6


module divider$stages$6$d_r(d,q,clock);
    
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
          
endmodule // divider$stages$6$d_r


module divider$stages$6$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$6$neg_r


module divider$stages$6$p_r(d,q,clock);
    
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
          
endmodule // divider$stages$6$p_r


module divider$stages$6$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$6$valid_r


module divider$stages$6$x_r(d,q,clock);
    
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
          
endmodule // divider$stages$6$x_r


module divider$stages$7(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
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
    divider$stages$7$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    divider$stages$7$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    divider$stages$7$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    divider$stages$7$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    divider$stages$7$neg_r neg_r(
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
    
endmodule // divider$stages$7


module divider$stages$7$d_r(d,q,clock);
    
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
          
endmodule // divider$stages$7$d_r


module divider$stages$7$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$7$neg_r


module divider$stages$7$p_r(d,q,clock);
    
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
          
endmodule // divider$stages$7$p_r


module divider$stages$7$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$7$valid_r


module divider$stages$7$x_r(d,q,clock);
    
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
          
endmodule // divider$stages$7$x_r


module divider$stages$8(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
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
    divider$stages$8$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    divider$stages$8$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    divider$stages$8$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    divider$stages$8$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    divider$stages$8$neg_r neg_r(
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
    
endmodule // divider$stages$8


module divider$stages$8$d_r(d,q,clock);
    
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
          
endmodule // divider$stages$8$d_r


module divider$stages$8$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$8$neg_r


module divider$stages$8$p_r(d,q,clock);
    
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
          
endmodule // divider$stages$8$p_r


module divider$stages$8$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$8$valid_r


module divider$stages$8$x_r(d,q,clock);
    
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
          
endmodule // divider$stages$8$x_r


module divider$stages$9(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
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
    divider$stages$9$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    divider$stages$9$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    divider$stages$9$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    divider$stages$9$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    divider$stages$9$neg_r neg_r(
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
    
endmodule // divider$stages$9


module divider$stages$9$d_r(d,q,clock);
    
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
          
endmodule // divider$stages$9$d_r


module divider$stages$9$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$9$neg_r


module divider$stages$9$p_r(d,q,clock);
    
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
          
endmodule // divider$stages$9$p_r


module divider$stages$9$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$9$valid_r


module divider$stages$9$x_r(d,q,clock);
    
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
          
endmodule // divider$stages$9$x_r
