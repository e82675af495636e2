

module pixel_bus(clock,start,clear,width,height,background,color_base,color_pitch,depth_base,depth_pitch,inp$valid,inp$ready,inp$x,inp$y,inp$z,inp$rgb0,inp$rgb1,inp$rgb2,zr$ar_valid,zr$ar_ready,zr$ar_addr,zr$ar_len,zr$ar_size,zr$ar_burst,zr$r_valid,zr$r_ready,zr$r_data,zr$r_resp,zw$aw_valid,zw$aw_ready,zw$aw_addr,zw$aw_len,zw$aw_size,zw$aw_burst,zw$w_valid,zw$w_ready,zw$w_data,zw$w_strb,zw$w_last,zw$b_valid,zw$b_ready,zw$b_resp,cw$aw_valid,cw$aw_ready,cw$aw_addr,cw$aw_len,cw$aw_size,cw$aw_burst,cw$w_valid,cw$w_ready,cw$w_data,cw$w_strb,cw$w_last,cw$b_valid,cw$b_ready,cw$b_resp,idle,error);
    
    // Module arguments
    input wire  clock;
    input wire  start;
    input wire  clear;
    input wire  [10:0] width;
    input wire  [10:0] height;
    input wire  [23:0] background;
    input wire  [31:0] color_base;
    input wire  [15:0] color_pitch;
    input wire  [31:0] depth_base;
    input wire  [15:0] depth_pitch;
    input wire  inp$valid;
    output reg  inp$ready;
    input wire  [9:0] inp$x;
    input wire  [9:0] inp$y;
    input wire  [15:0] inp$z;
    input wire  [7:0] inp$rgb0;
    input wire  [7:0] inp$rgb1;
    input wire  [7:0] inp$rgb2;
    output reg  zr$ar_valid;
    input wire  zr$ar_ready;
    output reg  [31:0] zr$ar_addr;
    output reg  [7:0] zr$ar_len;
    output reg  [2:0] zr$ar_size;
    output reg  [1:0] zr$ar_burst;
    input wire  zr$r_valid;
    output reg  zr$r_ready;
    input wire  [31:0] zr$r_data;
    input wire  [1:0] zr$r_resp;
    output reg  zw$aw_valid;
    input wire  zw$aw_ready;
    output reg  [31:0] zw$aw_addr;
    output reg  [7:0] zw$aw_len;
    output reg  [2:0] zw$aw_size;
    output reg  [1:0] zw$aw_burst;
    output reg  zw$w_valid;
    input wire  zw$w_ready;
    output reg  [31:0] zw$w_data;
    output reg  [3:0] zw$w_strb;
    output reg  zw$w_last;
    input wire  zw$b_valid;
    output reg  zw$b_ready;
    input wire  [1:0] zw$b_resp;
    output reg  cw$aw_valid;
    input wire  cw$aw_ready;
    output reg  [31:0] cw$aw_addr;
    output reg  [7:0] cw$aw_len;
    output reg  [2:0] cw$aw_size;
    output reg  [1:0] cw$aw_burst;
    output reg  cw$w_valid;
    input wire  cw$w_ready;
    output reg  [31:0] cw$w_data;
    output reg  [3:0] cw$w_strb;
    output reg  cw$w_last;
    input wire  cw$b_valid;
    output reg  cw$b_ready;
    input wire  [1:0] cw$b_resp;
    output reg  idle;
    output reg  error;
    
    // Stub signals
    reg  [1:0] phase$d;
    wire  [1:0] phase$q;
    reg  phase$clock;
    reg  [10:0] cx$d;
    wire  [10:0] cx$q;
    reg  cx$clock;
    reg  [10:0] cy$d;
    wire  [10:0] cy$q;
    reg  cy$clock;
    reg  [31:0] in_zaddr$0$d;
    wire  [31:0] in_zaddr$0$q;
    reg  in_zaddr$0$clock;
    reg  [31:0] in_zaddr$1$d;
    wire  [31:0] in_zaddr$1$q;
    reg  in_zaddr$1$clock;
    reg  [31:0] in_caddr$0$d;
    wire  [31:0] in_caddr$0$q;
    reg  in_caddr$0$clock;
    reg  [31:0] in_caddr$1$d;
    wire  [31:0] in_caddr$1$q;
    reg  in_caddr$1$clock;
    reg  [15:0] in_z$0$d;
    wire  [15:0] in_z$0$q;
    reg  in_z$0$clock;
    reg  [15:0] in_z$1$d;
    wire  [15:0] in_z$1$q;
    reg  in_z$1$clock;
    reg  [23:0] in_rgb$0$d;
    wire  [23:0] in_rgb$0$q;
    reg  in_rgb$0$clock;
    reg  [23:0] in_rgb$1$d;
    wire  [23:0] in_rgb$1$q;
    reg  in_rgb$1$clock;
    reg  [1:0] in_head$d;
    wire  [1:0] in_head$q;
    reg  in_head$clock;
    reg  [1:0] in_tail$d;
    wire  [1:0] in_tail$q;
    reg  in_tail$clock;
    reg  [31:0] e_zaddr$0$d;
    wire  [31:0] e_zaddr$0$q;
    reg  e_zaddr$0$clock;
    reg  [31:0] e_zaddr$1$d;
    wire  [31:0] e_zaddr$1$q;
    reg  e_zaddr$1$clock;
    reg  [31:0] e_zaddr$2$d;
    wire  [31:0] e_zaddr$2$q;
    reg  e_zaddr$2$clock;
    reg  [31:0] e_zaddr$3$d;
    wire  [31:0] e_zaddr$3$q;
    reg  e_zaddr$3$clock;
    reg  [31:0] e_zaddr$4$d;
    wire  [31:0] e_zaddr$4$q;
    reg  e_zaddr$4$clock;
    reg  [31:0] e_zaddr$5$d;
    wire  [31:0] e_zaddr$5$q;
    reg  e_zaddr$5$clock;
    reg  [31:0] e_zaddr$6$d;
    wire  [31:0] e_zaddr$6$q;
    reg  e_zaddr$6$clock;
    reg  [31:0] e_zaddr$7$d;
    wire  [31:0] e_zaddr$7$q;
    reg  e_zaddr$7$clock;
    reg  [31:0] e_zaddr$8$d;
    wire  [31:0] e_zaddr$8$q;
    reg  e_zaddr$8$clock;
    reg  [31:0] e_zaddr$9$d;
    wire  [31:0] e_zaddr$9$q;
    reg  e_zaddr$9$clock;
    reg  [31:0] e_zaddr$10$d;
    wire  [31:0] e_zaddr$10$q;
    reg  e_zaddr$10$clock;
    reg  [31:0] e_zaddr$11$d;
    wire  [31:0] e_zaddr$11$q;
    reg  e_zaddr$11$clock;
    reg  [31:0] e_zaddr$12$d;
    wire  [31:0] e_zaddr$12$q;
    reg  e_zaddr$12$clock;
    reg  [31:0] e_zaddr$13$d;
    wire  [31:0] e_zaddr$13$q;
    reg  e_zaddr$13$clock;
    reg  [31:0] e_zaddr$14$d;
    wire  [31:0] e_zaddr$14$q;
    reg  e_zaddr$14$clock;
    reg  [31:0] e_zaddr$15$d;
    wire  [31:0] e_zaddr$15$q;
    reg  e_zaddr$15$clock;
    reg  [31:0] e_caddr$0$d;
    wire  [31:0] e_caddr$0$q;
    reg  e_caddr$0$clock;
    reg  [31:0] e_caddr$1$d;
    wire  [31:0] e_caddr$1$q;
    reg  e_caddr$1$clock;
    reg  [31:0] e_caddr$2$d;
    wire  [31:0] e_caddr$2$q;
    reg  e_caddr$2$clock;
    reg  [31:0] e_caddr$3$d;
    wire  [31:0] e_caddr$3$q;
    reg  e_caddr$3$clock;
    reg  [31:0] e_caddr$4$d;
    wire  [31:0] e_caddr$4$q;
    reg  e_caddr$4$clock;
    reg  [31:0] e_caddr$5$d;
    wire  [31:0] e_caddr$5$q;
    reg  e_caddr$5$clock;
    reg  [31:0] e_caddr$6$d;
    wire  [31:0] e_caddr$6$q;
    reg  e_caddr$6$clock;
    reg  [31:0] e_caddr$7$d;
    wire  [31:0] e_caddr$7$q;
    reg  e_caddr$7$clock;
    reg  [31:0] e_caddr$8$d;
    wire  [31:0] e_caddr$8$q;
    reg  e_caddr$8$clock;
    reg  [31:0] e_caddr$9$d;
    wire  [31:0] e_caddr$9$q;
    reg  e_caddr$9$clock;
    reg  [31:0] e_caddr$10$d;
    wire  [31:0] e_caddr$10$q;
    reg  e_caddr$10$clock;
    reg  [31:0] e_caddr$11$d;
    wire  [31:0] e_caddr$11$q;
    reg  e_caddr$11$clock;
    reg  [31:0] e_caddr$12$d;
    wire  [31:0] e_caddr$12$q;
    reg  e_caddr$12$clock;
    reg  [31:0] e_caddr$13$d;
    wire  [31:0] e_caddr$13$q;
    reg  e_caddr$13$clock;
    reg  [31:0] e_caddr$14$d;
    wire  [31:0] e_caddr$14$q;
    reg  e_caddr$14$clock;
    reg  [31:0] e_caddr$15$d;
    wire  [31:0] e_caddr$15$q;
    reg  e_caddr$15$clock;
    reg  [15:0] e_z$0$d;
    wire  [15:0] e_z$0$q;
    reg  e_z$0$clock;
    reg  [15:0] e_z$1$d;
    wire  [15:0] e_z$1$q;
    reg  e_z$1$clock;
    reg  [15:0] e_z$2$d;
    wire  [15:0] e_z$2$q;
    reg  e_z$2$clock;
    reg  [15:0] e_z$3$d;
    wire  [15:0] e_z$3$q;
    reg  e_z$3$clock;
    reg  [15:0] e_z$4$d;
    wire  [15:0] e_z$4$q;
    reg  e_z$4$clock;
    reg  [15:0] e_z$5$d;
    wire  [15:0] e_z$5$q;
    reg  e_z$5$clock;
    reg  [15:0] e_z$6$d;
    wire  [15:0] e_z$6$q;
    reg  e_z$6$clock;
    reg  [15:0] e_z$7$d;
    wire  [15:0] e_z$7$q;
    reg  e_z$7$clock;
    reg  [15:0] e_z$8$d;
    wire  [15:0] e_z$8$q;
    reg  e_z$8$clock;
    reg  [15:0] e_z$9$d;
    wire  [15:0] e_z$9$q;
    reg  e_z$9$clock;
    reg  [15:0] e_z$10$d;
    wire  [15:0] e_z$10$q;
    reg  e_z$10$clock;
    reg  [15:0] e_z$11$d;
    wire  [15:0] e_z$11$q;
    reg  e_z$11$clock;
    reg  [15:0] e_z$12$d;
    wire  [15:0] e_z$12$q;
    reg  e_z$12$clock;
    reg  [15:0] e_z$13$d;
    wire  [15:0] e_z$13$q;
    reg  e_z$13$clock;
    reg  [15:0] e_z$14$d;
    wire  [15:0] e_z$14$q;
    reg  e_z$14$clock;
    reg  [15:0] e_z$15$d;
    wire  [15:0] e_z$15$q;
    reg  e_z$15$clock;
    reg  [23:0] e_rgb$0$d;
    wire  [23:0] e_rgb$0$q;
    reg  e_rgb$0$clock;
    reg  [23:0] e_rgb$1$d;
    wire  [23:0] e_rgb$1$q;
    reg  e_rgb$1$clock;
    reg  [23:0] e_rgb$2$d;
    wire  [23:0] e_rgb$2$q;
    reg  e_rgb$2$clock;
    reg  [23:0] e_rgb$3$d;
    wire  [23:0] e_rgb$3$q;
    reg  e_rgb$3$clock;
    reg  [23:0] e_rgb$4$d;
    wire  [23:0] e_rgb$4$q;
    reg  e_rgb$4$clock;
    reg  [23:0] e_rgb$5$d;
    wire  [23:0] e_rgb$5$q;
    reg  e_rgb$5$clock;
    reg  [23:0] e_rgb$6$d;
    wire  [23:0] e_rgb$6$q;
    reg  e_rgb$6$clock;
    reg  [23:0] e_rgb$7$d;
    wire  [23:0] e_rgb$7$q;
    reg  e_rgb$7$clock;
    reg  [23:0] e_rgb$8$d;
    wire  [23:0] e_rgb$8$q;
    reg  e_rgb$8$clock;
    reg  [23:0] e_rgb$9$d;
    wire  [23:0] e_rgb$9$q;
    reg  e_rgb$9$clock;
    reg  [23:0] e_rgb$10$d;
    wire  [23:0] e_rgb$10$q;
    reg  e_rgb$10$clock;
    reg  [23:0] e_rgb$11$d;
    wire  [23:0] e_rgb$11$q;
    reg  e_rgb$11$clock;
    reg  [23:0] e_rgb$12$d;
    wire  [23:0] e_rgb$12$q;
    reg  e_rgb$12$clock;
    reg  [23:0] e_rgb$13$d;
    wire  [23:0] e_rgb$13$q;
    reg  e_rgb$13$clock;
    reg  [23:0] e_rgb$14$d;
    wire  [23:0] e_rgb$14$q;
    reg  e_rgb$14$clock;
    reg  [23:0] e_rgb$15$d;
    wire  [23:0] e_rgb$15$q;
    reg  e_rgb$15$clock;
    reg  e_pass$0$d;
    wire  e_pass$0$q;
    reg  e_pass$0$clock;
    reg  e_pass$1$d;
    wire  e_pass$1$q;
    reg  e_pass$1$clock;
    reg  e_pass$2$d;
    wire  e_pass$2$q;
    reg  e_pass$2$clock;
    reg  e_pass$3$d;
    wire  e_pass$3$q;
    reg  e_pass$3$clock;
    reg  e_pass$4$d;
    wire  e_pass$4$q;
    reg  e_pass$4$clock;
    reg  e_pass$5$d;
    wire  e_pass$5$q;
    reg  e_pass$5$clock;
    reg  e_pass$6$d;
    wire  e_pass$6$q;
    reg  e_pass$6$clock;
    reg  e_pass$7$d;
    wire  e_pass$7$q;
    reg  e_pass$7$clock;
    reg  e_pass$8$d;
    wire  e_pass$8$q;
    reg  e_pass$8$clock;
    reg  e_pass$9$d;
    wire  e_pass$9$q;
    reg  e_pass$9$clock;
    reg  e_pass$10$d;
    wire  e_pass$10$q;
    reg  e_pass$10$clock;
    reg  e_pass$11$d;
    wire  e_pass$11$q;
    reg  e_pass$11$clock;
    reg  e_pass$12$d;
    wire  e_pass$12$q;
    reg  e_pass$12$clock;
    reg  e_pass$13$d;
    wire  e_pass$13$q;
    reg  e_pass$13$clock;
    reg  e_pass$14$d;
    wire  e_pass$14$q;
    reg  e_pass$14$clock;
    reg  e_pass$15$d;
    wire  e_pass$15$q;
    reg  e_pass$15$clock;
    reg  e_live$0$d;
    wire  e_live$0$q;
    reg  e_live$0$clock;
    reg  e_live$1$d;
    wire  e_live$1$q;
    reg  e_live$1$clock;
    reg  e_live$2$d;
    wire  e_live$2$q;
    reg  e_live$2$clock;
    reg  e_live$3$d;
    wire  e_live$3$q;
    reg  e_live$3$clock;
    reg  e_live$4$d;
    wire  e_live$4$q;
    reg  e_live$4$clock;
    reg  e_live$5$d;
    wire  e_live$5$q;
    reg  e_live$5$clock;
    reg  e_live$6$d;
    wire  e_live$6$q;
    reg  e_live$6$clock;
    reg  e_live$7$d;
    wire  e_live$7$q;
    reg  e_live$7$clock;
    reg  e_live$8$d;
    wire  e_live$8$q;
    reg  e_live$8$clock;
    reg  e_live$9$d;
    wire  e_live$9$q;
    reg  e_live$9$clock;
    reg  e_live$10$d;
    wire  e_live$10$q;
    reg  e_live$10$clock;
    reg  e_live$11$d;
    wire  e_live$11$q;
    reg  e_live$11$clock;
    reg  e_live$12$d;
    wire  e_live$12$q;
    reg  e_live$12$clock;
    reg  e_live$13$d;
    wire  e_live$13$q;
    reg  e_live$13$clock;
    reg  e_live$14$d;
    wire  e_live$14$q;
    reg  e_live$14$clock;
    reg  e_live$15$d;
    wire  e_live$15$q;
    reg  e_live$15$clock;
    reg  [4:0] head$d;
    wire  [4:0] head$q;
    reg  head$clock;
    reg  [4:0] written$d;
    wire  [4:0] written$q;
    reg  written$clock;
    reg  [4:0] tested$d;
    wire  [4:0] tested$q;
    reg  tested$clock;
    reg  [4:0] tail$d;
    wire  [4:0] tail$q;
    reg  tail$clock;
    reg  ar_valid$d;
    wire  ar_valid$q;
    reg  ar_valid$clock;
    reg  [31:0] ar_addr$d;
    wire  [31:0] ar_addr$q;
    reg  ar_addr$clock;
    reg  zaw_valid$d;
    wire  zaw_valid$q;
    reg  zaw_valid$clock;
    reg  [31:0] zaw_addr$d;
    wire  [31:0] zaw_addr$q;
    reg  zaw_addr$clock;
    reg  zw_valid$d;
    wire  zw_valid$q;
    reg  zw_valid$clock;
    reg  [31:0] zw_data$d;
    wire  [31:0] zw_data$q;
    reg  zw_data$clock;
    reg  caw_valid$d;
    wire  caw_valid$q;
    reg  caw_valid$clock;
    reg  [31:0] caw_addr$d;
    wire  [31:0] caw_addr$q;
    reg  caw_addr$clock;
    reg  cw_valid$d;
    wire  cw_valid$q;
    reg  cw_valid$clock;
    reg  [31:0] cw_data$d;
    wire  [31:0] cw_data$q;
    reg  cw_data$clock;
    reg  [7:0] z_pending$d;
    wire  [7:0] z_pending$q;
    reg  z_pending$clock;
    reg  [7:0] c_pending$d;
    wire  [7:0] c_pending$q;
    reg  c_pending$clock;
    reg  [4:0] credit$d;
    wire  [4:0] credit$q;
    reg  credit$clock;
    reg  err$d;
    wire  err$q;
    reg  err$clock;
    reg  [11:0] zmul$a;
    reg  [16:0] zmul$b;
    wire  [31:0] zmul$p;
    reg  [11:0] cmul$a;
    reg  [16:0] cmul$b;
    wire  [31:0] cmul$p;
    reg  [10:0] x4$hi;
    reg  [1:0] x4$lo;
    wire  [12:0] x4$out;
    reg  [7:0] rg$hi;
    reg  [7:0] rg$lo;
    wire  [15:0] rg$out;
    reg  [15:0] rgb$hi;
    reg  [7:0] rgb$lo;
    wire  [23:0] rgb$out;
    
    // Local signals
    reg  [10:0] y_sel;
    reg  [31:0] zaddr;
    reg  [31:0] caddr;
    reg  [15:0] zero;
    reg  [15:0] far;
    reg  [3:0] w_i;
    reg  [3:0] h_i;
    reg  [3:0] t_i;
    reg  [3:0] tail_i;
    reg  clearing;
    reg  drawing;
    reg  idle_now;
    reg  hazard;
    reg  [4:0] count;
    reg  [1:0] in_count;
    reg  [31:0] oldest_zaddr;
    reg  [31:0] oldest_caddr;
    reg  [15:0] oldest_z;
    reg  [23:0] oldest_rgb;
    reg  take;
    reg  enter;
    reg  can_write;
    reg  load;
    reg  [31:0] w_zaddr;
    reg  [31:0] w_caddr;
    reg  [15:0] w_z;
    reg  [23:0] w_rgb;
    reg  w_pass;
    reg  h_pass;
    reg  [15:0] t_z;
    reg  [15:0] old_z;
    reg  [4:0] credit_in;
    reg  retire;
    reg  consume;
    reg  [10:0] cx_next;
    reg  [10:0] cy_next;
    
    // Sub module instances
    pixel_bus$phase phase(
        .d(phase$d),
        .q(phase$q),
        .clock(phase$clock)
    );
    pixel_bus$cx cx(
        .d(cx$d),
        .q(cx$q),
        .clock(cx$clock)
    );
    pixel_bus$cy cy(
        .d(cy$d),
        .q(cy$q),
        .clock(cy$clock)
    );
    pixel_bus$in_zaddr$0 in_zaddr$0(
        .d(in_zaddr$0$d),
        .q(in_zaddr$0$q),
        .clock(in_zaddr$0$clock)
    );
    pixel_bus$in_zaddr$1 in_zaddr$1(
        .d(in_zaddr$1$d),
        .q(in_zaddr$1$q),
        .clock(in_zaddr$1$clock)
    );
    pixel_bus$in_caddr$0 in_caddr$0(
        .d(in_caddr$0$d),
        .q(in_caddr$0$q),
        .clock(in_caddr$0$clock)
    );
    pixel_bus$in_caddr$1 in_caddr$1(
        .d(in_caddr$1$d),
        .q(in_caddr$1$q),
        .clock(in_caddr$1$clock)
    );
    pixel_bus$in_z$0 in_z$0(
        .d(in_z$0$d),
        .q(in_z$0$q),
        .clock(in_z$0$clock)
    );
    pixel_bus$in_z$1 in_z$1(
        .d(in_z$1$d),
        .q(in_z$1$q),
        .clock(in_z$1$clock)
    );
    pixel_bus$in_rgb$0 in_rgb$0(
        .d(in_rgb$0$d),
        .q(in_rgb$0$q),
        .clock(in_rgb$0$clock)
    );
    pixel_bus$in_rgb$1 in_rgb$1(
        .d(in_rgb$1$d),
        .q(in_rgb$1$q),
        .clock(in_rgb$1$clock)
    );
    pixel_bus$in_head in_head(
        .d(in_head$d),
        .q(in_head$q),
        .clock(in_head$clock)
    );
    pixel_bus$in_tail in_tail(
        .d(in_tail$d),
        .q(in_tail$q),
        .clock(in_tail$clock)
    );
    pixel_bus$e_zaddr$0 e_zaddr$0(
        .d(e_zaddr$0$d),
        .q(e_zaddr$0$q),
        .clock(e_zaddr$0$clock)
    );
    pixel_bus$e_zaddr$1 e_zaddr$1(
        .d(e_zaddr$1$d),
        .q(e_zaddr$1$q),
        .clock(e_zaddr$1$clock)
    );
    pixel_bus$e_zaddr$2 e_zaddr$2(
        .d(e_zaddr$2$d),
        .q(e_zaddr$2$q),
        .clock(e_zaddr$2$clock)
    );
    pixel_bus$e_zaddr$3 e_zaddr$3(
        .d(e_zaddr$3$d),
        .q(e_zaddr$3$q),
        .clock(e_zaddr$3$clock)
    );
    pixel_bus$e_zaddr$4 e_zaddr$4(
        .d(e_zaddr$4$d),
        .q(e_zaddr$4$q),
        .clock(e_zaddr$4$clock)
    );
    pixel_bus$e_zaddr$5 e_zaddr$5(
        .d(e_zaddr$5$d),
        .q(e_zaddr$5$q),
        .clock(e_zaddr$5$clock)
    );
    pixel_bus$e_zaddr$6 e_zaddr$6(
        .d(e_zaddr$6$d),
        .q(e_zaddr$6$q),
        .clock(e_zaddr$6$clock)
    );
    pixel_bus$e_zaddr$7 e_zaddr$7(
        .d(e_zaddr$7$d),
        .q(e_zaddr$7$q),
        .clock(e_zaddr$7$clock)
    );
    pixel_bus$e_zaddr$8 e_zaddr$8(
        .d(e_zaddr$8$d),
        .q(e_zaddr$8$q),
        .clock(e_zaddr$8$clock)
    );
    pixel_bus$e_zaddr$9 e_zaddr$9(
        .d(e_zaddr$9$d),
        .q(e_zaddr$9$q),
        .clock(e_zaddr$9$clock)
    );
    pixel_bus$e_zaddr$10 e_zaddr$10(
        .d(e_zaddr$10$d),
        .q(e_zaddr$10$q),
        .clock(e_zaddr$10$clock)
    );
    pixel_bus$e_zaddr$11 e_zaddr$11(
        .d(e_zaddr$11$d),
        .q(e_zaddr$11$q),
        .clock(e_zaddr$11$clock)
    );
    pixel_bus$e_zaddr$12 e_zaddr$12(
        .d(e_zaddr$12$d),
        .q(e_zaddr$12$q),
        .clock(e_zaddr$12$clock)
    );
    pixel_bus$e_zaddr$13 e_zaddr$13(
        .d(e_zaddr$13$d),
        .q(e_zaddr$13$q),
        .clock(e_zaddr$13$clock)
    );
    pixel_bus$e_zaddr$14 e_zaddr$14(
        .d(e_zaddr$14$d),
        .q(e_zaddr$14$q),
        .clock(e_zaddr$14$clock)
    );
    pixel_bus$e_zaddr$15 e_zaddr$15(
        .d(e_zaddr$15$d),
        .q(e_zaddr$15$q),
        .clock(e_zaddr$15$clock)
    );
    pixel_bus$e_caddr$0 e_caddr$0(
        .d(e_caddr$0$d),
        .q(e_caddr$0$q),
        .clock(e_caddr$0$clock)
    );
    pixel_bus$e_caddr$1 e_caddr$1(
        .d(e_caddr$1$d),
        .q(e_caddr$1$q),
        .clock(e_caddr$1$clock)
    );
    pixel_bus$e_caddr$2 e_caddr$2(
        .d(e_caddr$2$d),
        .q(e_caddr$2$q),
        .clock(e_caddr$2$clock)
    );
    pixel_bus$e_caddr$3 e_caddr$3(
        .d(e_caddr$3$d),
        .q(e_caddr$3$q),
        .clock(e_caddr$3$clock)
    );
    pixel_bus$e_caddr$4 e_caddr$4(
        .d(e_caddr$4$d),
        .q(e_caddr$4$q),
        .clock(e_caddr$4$clock)
    );
    pixel_bus$e_caddr$5 e_caddr$5(
        .d(e_caddr$5$d),
        .q(e_caddr$5$q),
        .clock(e_caddr$5$clock)
    );
    pixel_bus$e_caddr$6 e_caddr$6(
        .d(e_caddr$6$d),
        .q(e_caddr$6$q),
        .clock(e_caddr$6$clock)
    );
    pixel_bus$e_caddr$7 e_caddr$7(
        .d(e_caddr$7$d),
        .q(e_caddr$7$q),
        .clock(e_caddr$7$clock)
    );
    pixel_bus$e_caddr$8 e_caddr$8(
        .d(e_caddr$8$d),
        .q(e_caddr$8$q),
        .clock(e_caddr$8$clock)
    );
    pixel_bus$e_caddr$9 e_caddr$9(
        .d(e_caddr$9$d),
        .q(e_caddr$9$q),
        .clock(e_caddr$9$clock)
    );
    pixel_bus$e_caddr$10 e_caddr$10(
        .d(e_caddr$10$d),
        .q(e_caddr$10$q),
        .clock(e_caddr$10$clock)
    );
    pixel_bus$e_caddr$11 e_caddr$11(
        .d(e_caddr$11$d),
        .q(e_caddr$11$q),
        .clock(e_caddr$11$clock)
    );
    pixel_bus$e_caddr$12 e_caddr$12(
        .d(e_caddr$12$d),
        .q(e_caddr$12$q),
        .clock(e_caddr$12$clock)
    );
    pixel_bus$e_caddr$13 e_caddr$13(
        .d(e_caddr$13$d),
        .q(e_caddr$13$q),
        .clock(e_caddr$13$clock)
    );
    pixel_bus$e_caddr$14 e_caddr$14(
        .d(e_caddr$14$d),
        .q(e_caddr$14$q),
        .clock(e_caddr$14$clock)
    );
    pixel_bus$e_caddr$15 e_caddr$15(
        .d(e_caddr$15$d),
        .q(e_caddr$15$q),
        .clock(e_caddr$15$clock)
    );
    pixel_bus$e_z$0 e_z$0(
        .d(e_z$0$d),
        .q(e_z$0$q),
        .clock(e_z$0$clock)
    );
    pixel_bus$e_z$1 e_z$1(
        .d(e_z$1$d),
        .q(e_z$1$q),
        .clock(e_z$1$clock)
    );
    pixel_bus$e_z$2 e_z$2(
        .d(e_z$2$d),
        .q(e_z$2$q),
        .clock(e_z$2$clock)
    );
    pixel_bus$e_z$3 e_z$3(
        .d(e_z$3$d),
        .q(e_z$3$q),
        .clock(e_z$3$clock)
    );
    pixel_bus$e_z$4 e_z$4(
        .d(e_z$4$d),
        .q(e_z$4$q),
        .clock(e_z$4$clock)
    );
    pixel_bus$e_z$5 e_z$5(
        .d(e_z$5$d),
        .q(e_z$5$q),
        .clock(e_z$5$clock)
    );
    pixel_bus$e_z$6 e_z$6(
        .d(e_z$6$d),
        .q(e_z$6$q),
        .clock(e_z$6$clock)
    );
    pixel_bus$e_z$7 e_z$7(
        .d(e_z$7$d),
        .q(e_z$7$q),
        .clock(e_z$7$clock)
    );
    pixel_bus$e_z$8 e_z$8(
        .d(e_z$8$d),
        .q(e_z$8$q),
        .clock(e_z$8$clock)
    );
    pixel_bus$e_z$9 e_z$9(
        .d(e_z$9$d),
        .q(e_z$9$q),
        .clock(e_z$9$clock)
    );
    pixel_bus$e_z$10 e_z$10(
        .d(e_z$10$d),
        .q(e_z$10$q),
        .clock(e_z$10$clock)
    );
    pixel_bus$e_z$11 e_z$11(
        .d(e_z$11$d),
        .q(e_z$11$q),
        .clock(e_z$11$clock)
    );
    pixel_bus$e_z$12 e_z$12(
        .d(e_z$12$d),
        .q(e_z$12$q),
        .clock(e_z$12$clock)
    );
    pixel_bus$e_z$13 e_z$13(
        .d(e_z$13$d),
        .q(e_z$13$q),
        .clock(e_z$13$clock)
    );
    pixel_bus$e_z$14 e_z$14(
        .d(e_z$14$d),
        .q(e_z$14$q),
        .clock(e_z$14$clock)
    );
    pixel_bus$e_z$15 e_z$15(
        .d(e_z$15$d),
        .q(e_z$15$q),
        .clock(e_z$15$clock)
    );
    pixel_bus$e_rgb$0 e_rgb$0(
        .d(e_rgb$0$d),
        .q(e_rgb$0$q),
        .clock(e_rgb$0$clock)
    );
    pixel_bus$e_rgb$1 e_rgb$1(
        .d(e_rgb$1$d),
        .q(e_rgb$1$q),
        .clock(e_rgb$1$clock)
    );
    pixel_bus$e_rgb$2 e_rgb$2(
        .d(e_rgb$2$d),
        .q(e_rgb$2$q),
        .clock(e_rgb$2$clock)
    );
    pixel_bus$e_rgb$3 e_rgb$3(
        .d(e_rgb$3$d),
        .q(e_rgb$3$q),
        .clock(e_rgb$3$clock)
    );
    pixel_bus$e_rgb$4 e_rgb$4(
        .d(e_rgb$4$d),
        .q(e_rgb$4$q),
        .clock(e_rgb$4$clock)
    );
    pixel_bus$e_rgb$5 e_rgb$5(
        .d(e_rgb$5$d),
        .q(e_rgb$5$q),
        .clock(e_rgb$5$clock)
    );
    pixel_bus$e_rgb$6 e_rgb$6(
        .d(e_rgb$6$d),
        .q(e_rgb$6$q),
        .clock(e_rgb$6$clock)
    );
    pixel_bus$e_rgb$7 e_rgb$7(
        .d(e_rgb$7$d),
        .q(e_rgb$7$q),
        .clock(e_rgb$7$clock)
    );
    pixel_bus$e_rgb$8 e_rgb$8(
        .d(e_rgb$8$d),
        .q(e_rgb$8$q),
        .clock(e_rgb$8$clock)
    );
    pixel_bus$e_rgb$9 e_rgb$9(
        .d(e_rgb$9$d),
        .q(e_rgb$9$q),
        .clock(e_rgb$9$clock)
    );
    pixel_bus$e_rgb$10 e_rgb$10(
        .d(e_rgb$10$d),
        .q(e_rgb$10$q),
        .clock(e_rgb$10$clock)
    );
    pixel_bus$e_rgb$11 e_rgb$11(
        .d(e_rgb$11$d),
        .q(e_rgb$11$q),
        .clock(e_rgb$11$clock)
    );
    pixel_bus$e_rgb$12 e_rgb$12(
        .d(e_rgb$12$d),
        .q(e_rgb$12$q),
        .clock(e_rgb$12$clock)
    );
    pixel_bus$e_rgb$13 e_rgb$13(
        .d(e_rgb$13$d),
        .q(e_rgb$13$q),
        .clock(e_rgb$13$clock)
    );
    pixel_bus$e_rgb$14 e_rgb$14(
        .d(e_rgb$14$d),
        .q(e_rgb$14$q),
        .clock(e_rgb$14$clock)
    );
    pixel_bus$e_rgb$15 e_rgb$15(
        .d(e_rgb$15$d),
        .q(e_rgb$15$q),
        .clock(e_rgb$15$clock)
    );
    pixel_bus$e_pass$0 e_pass$0(
        .d(e_pass$0$d),
        .q(e_pass$0$q),
        .clock(e_pass$0$clock)
    );
    pixel_bus$e_pass$1 e_pass$1(
        .d(e_pass$1$d),
        .q(e_pass$1$q),
        .clock(e_pass$1$clock)
    );
    pixel_bus$e_pass$2 e_pass$2(
        .d(e_pass$2$d),
        .q(e_pass$2$q),
        .clock(e_pass$2$clock)
    );
    pixel_bus$e_pass$3 e_pass$3(
        .d(e_pass$3$d),
        .q(e_pass$3$q),
        .clock(e_pass$3$clock)
    );
    pixel_bus$e_pass$4 e_pass$4(
        .d(e_pass$4$d),
        .q(e_pass$4$q),
        .clock(e_pass$4$clock)
    );
    pixel_bus$e_pass$5 e_pass$5(
        .d(e_pass$5$d),
        .q(e_pass$5$q),
        .clock(e_pass$5$clock)
    );
    pixel_bus$e_pass$6 e_pass$6(
        .d(e_pass$6$d),
        .q(e_pass$6$q),
        .clock(e_pass$6$clock)
    );
    pixel_bus$e_pass$7 e_pass$7(
        .d(e_pass$7$d),
        .q(e_pass$7$q),
        .clock(e_pass$7$clock)
    );
    pixel_bus$e_pass$8 e_pass$8(
        .d(e_pass$8$d),
        .q(e_pass$8$q),
        .clock(e_pass$8$clock)
    );
    pixel_bus$e_pass$9 e_pass$9(
        .d(e_pass$9$d),
        .q(e_pass$9$q),
        .clock(e_pass$9$clock)
    );
    pixel_bus$e_pass$10 e_pass$10(
        .d(e_pass$10$d),
        .q(e_pass$10$q),
        .clock(e_pass$10$clock)
    );
    pixel_bus$e_pass$11 e_pass$11(
        .d(e_pass$11$d),
        .q(e_pass$11$q),
        .clock(e_pass$11$clock)
    );
    pixel_bus$e_pass$12 e_pass$12(
        .d(e_pass$12$d),
        .q(e_pass$12$q),
        .clock(e_pass$12$clock)
    );
    pixel_bus$e_pass$13 e_pass$13(
        .d(e_pass$13$d),
        .q(e_pass$13$q),
        .clock(e_pass$13$clock)
    );
    pixel_bus$e_pass$14 e_pass$14(
        .d(e_pass$14$d),
        .q(e_pass$14$q),
        .clock(e_pass$14$clock)
    );
    pixel_bus$e_pass$15 e_pass$15(
        .d(e_pass$15$d),
        .q(e_pass$15$q),
        .clock(e_pass$15$clock)
    );
    pixel_bus$e_live$0 e_live$0(
        .d(e_live$0$d),
        .q(e_live$0$q),
        .clock(e_live$0$clock)
    );
    pixel_bus$e_live$1 e_live$1(
        .d(e_live$1$d),
        .q(e_live$1$q),
        .clock(e_live$1$clock)
    );
    pixel_bus$e_live$2 e_live$2(
        .d(e_live$2$d),
        .q(e_live$2$q),
        .clock(e_live$2$clock)
    );
    pixel_bus$e_live$3 e_live$3(
        .d(e_live$3$d),
        .q(e_live$3$q),
        .clock(e_live$3$clock)
    );
    pixel_bus$e_live$4 e_live$4(
        .d(e_live$4$d),
        .q(e_live$4$q),
        .clock(e_live$4$clock)
    );
    pixel_bus$e_live$5 e_live$5(
        .d(e_live$5$d),
        .q(e_live$5$q),
        .clock(e_live$5$clock)
    );
    pixel_bus$e_live$6 e_live$6(
        .d(e_live$6$d),
        .q(e_live$6$q),
        .clock(e_live$6$clock)
    );
    pixel_bus$e_live$7 e_live$7(
        .d(e_live$7$d),
        .q(e_live$7$q),
        .clock(e_live$7$clock)
    );
    pixel_bus$e_live$8 e_live$8(
        .d(e_live$8$d),
        .q(e_live$8$q),
        .clock(e_live$8$clock)
    );
    pixel_bus$e_live$9 e_live$9(
        .d(e_live$9$d),
        .q(e_live$9$q),
        .clock(e_live$9$clock)
    );
    pixel_bus$e_live$10 e_live$10(
        .d(e_live$10$d),
        .q(e_live$10$q),
        .clock(e_live$10$clock)
    );
    pixel_bus$e_live$11 e_live$11(
        .d(e_live$11$d),
        .q(e_live$11$q),
        .clock(e_live$11$clock)
    );
    pixel_bus$e_live$12 e_live$12(
        .d(e_live$12$d),
        .q(e_live$12$q),
        .clock(e_live$12$clock)
    );
    pixel_bus$e_live$13 e_live$13(
        .d(e_live$13$d),
        .q(e_live$13$q),
        .clock(e_live$13$clock)
    );
    pixel_bus$e_live$14 e_live$14(
        .d(e_live$14$d),
        .q(e_live$14$q),
        .clock(e_live$14$clock)
    );
    pixel_bus$e_live$15 e_live$15(
        .d(e_live$15$d),
        .q(e_live$15$q),
        .clock(e_live$15$clock)
    );
    pixel_bus$head head(
        .d(head$d),
        .q(head$q),
        .clock(head$clock)
    );
    pixel_bus$written written(
        .d(written$d),
        .q(written$q),
        .clock(written$clock)
    );
    pixel_bus$tested tested(
        .d(tested$d),
        .q(tested$q),
        .clock(tested$clock)
    );
    pixel_bus$tail tail(
        .d(tail$d),
        .q(tail$q),
        .clock(tail$clock)
    );
    pixel_bus$ar_valid ar_valid(
        .d(ar_valid$d),
        .q(ar_valid$q),
        .clock(ar_valid$clock)
    );
    pixel_bus$ar_addr ar_addr(
        .d(ar_addr$d),
        .q(ar_addr$q),
        .clock(ar_addr$clock)
    );
    pixel_bus$zaw_valid zaw_valid(
        .d(zaw_valid$d),
        .q(zaw_valid$q),
        .clock(zaw_valid$clock)
    );
    pixel_bus$zaw_addr zaw_addr(
        .d(zaw_addr$d),
        .q(zaw_addr$q),
        .clock(zaw_addr$clock)
    );
    pixel_bus$zw_valid zw_valid(
        .d(zw_valid$d),
        .q(zw_valid$q),
        .clock(zw_valid$clock)
    );
    pixel_bus$zw_data zw_data(
        .d(zw_data$d),
        .q(zw_data$q),
        .clock(zw_data$clock)
    );
    pixel_bus$caw_valid caw_valid(
        .d(caw_valid$d),
        .q(caw_valid$q),
        .clock(caw_valid$clock)
    );
    pixel_bus$caw_addr caw_addr(
        .d(caw_addr$d),
        .q(caw_addr$q),
        .clock(caw_addr$clock)
    );
    pixel_bus$cw_valid cw_valid(
        .d(cw_valid$d),
        .q(cw_valid$q),
        .clock(cw_valid$clock)
    );
    pixel_bus$cw_data cw_data(
        .d(cw_data$d),
        .q(cw_data$q),
        .clock(cw_data$clock)
    );
    pixel_bus$z_pending z_pending(
        .d(z_pending$d),
        .q(z_pending$q),
        .clock(z_pending$clock)
    );
    pixel_bus$c_pending c_pending(
        .d(c_pending$d),
        .q(c_pending$q),
        .clock(c_pending$clock)
    );
    pixel_bus$credit credit(
        .d(credit$d),
        .q(credit$q),
        .clock(credit$clock)
    );
    pixel_bus$err err(
        .d(err$d),
        .q(err$q),
        .clock(err$clock)
    );
    pixel_bus$zmul zmul(
        .a(zmul$a),
        .b(zmul$b),
        .p(zmul$p)
    );
    pixel_bus$cmul cmul(
        .a(cmul$a),
        .b(cmul$b),
        .p(cmul$p)
    );
    pixel_bus$x4 x4(
        .hi(x4$hi),
        .lo(x4$lo),
        .out(x4$out)
    );
    pixel_bus$rg rg(
        .hi(rg$hi),
        .lo(rg$lo),
        .out(rg$out)
    );
    pixel_bus$rgb rgb(
        .hi(rgb$hi),
        .lo(rgb$lo),
        .out(rgb$out)
    );
    
    // Update code
    always @(*) begin
        phase$clock = clock;
        cx$clock = clock;
        cy$clock = clock;
        in_head$clock = clock;
        in_tail$clock = clock;
        head$clock = clock;
        written$clock = clock;
        tested$clock = clock;
        tail$clock = clock;
        ar_valid$clock = clock;
        ar_addr$clock = clock;
        zaw_valid$clock = clock;
        zaw_addr$clock = clock;
        zw_valid$clock = clock;
        zw_data$clock = clock;
        caw_valid$clock = clock;
        caw_addr$clock = clock;
        cw_valid$clock = clock;
        cw_data$clock = clock;
        z_pending$clock = clock;
        c_pending$clock = clock;
        credit$clock = clock;
        err$clock = clock;
        phase$d = phase$q;
        cx$d = cx$q;
        cy$d = cy$q;
        in_head$d = in_head$q;
        in_tail$d = in_tail$q;
        head$d = head$q;
        written$d = written$q;
        tested$d = tested$q;
        tail$d = tail$q;
        ar_valid$d = ar_valid$q;
        ar_addr$d = ar_addr$q;
        zaw_valid$d = zaw_valid$q;
        zaw_addr$d = zaw_addr$q;
        zw_valid$d = zw_valid$q;
        zw_data$d = zw_data$q;
        caw_valid$d = caw_valid$q;
        caw_addr$d = caw_addr$q;
        cw_valid$d = cw_valid$q;
        cw_data$d = cw_data$q;
        z_pending$d = z_pending$q;
        c_pending$d = c_pending$q;
        credit$d = credit$q;
        err$d = err$q;
        in_zaddr$0$clock = clock;
        in_zaddr$0$d = in_zaddr$0$q;
        in_caddr$0$clock = clock;
        in_caddr$0$d = in_caddr$0$q;
        in_z$0$clock = clock;
        in_z$0$d = in_z$0$q;
        in_rgb$0$clock = clock;
        in_rgb$0$d = in_rgb$0$q;
        in_zaddr$1$clock = clock;
        in_zaddr$1$d = in_zaddr$1$q;
        in_caddr$1$clock = clock;
        in_caddr$1$d = in_caddr$1$q;
        in_z$1$clock = clock;
        in_z$1$d = in_z$1$q;
        in_rgb$1$clock = clock;
        in_rgb$1$d = in_rgb$1$q;
        e_zaddr$0$clock = clock;
        e_zaddr$0$d = e_zaddr$0$q;
        e_caddr$0$clock = clock;
        e_caddr$0$d = e_caddr$0$q;
        e_z$0$clock = clock;
        e_z$0$d = e_z$0$q;
        e_rgb$0$clock = clock;
        e_rgb$0$d = e_rgb$0$q;
        e_pass$0$clock = clock;
        e_pass$0$d = e_pass$0$q;
        e_live$0$clock = clock;
        e_live$0$d = e_live$0$q;
        e_zaddr$1$clock = clock;
        e_zaddr$1$d = e_zaddr$1$q;
        e_caddr$1$clock = clock;
        e_caddr$1$d = e_caddr$1$q;
        e_z$1$clock = clock;
        e_z$1$d = e_z$1$q;
        e_rgb$1$clock = clock;
        e_rgb$1$d = e_rgb$1$q;
        e_pass$1$clock = clock;
        e_pass$1$d = e_pass$1$q;
        e_live$1$clock = clock;
        e_live$1$d = e_live$1$q;
        e_zaddr$2$clock = clock;
        e_zaddr$2$d = e_zaddr$2$q;
        e_caddr$2$clock = clock;
        e_caddr$2$d = e_caddr$2$q;
        e_z$2$clock = clock;
        e_z$2$d = e_z$2$q;
        e_rgb$2$clock = clock;
        e_rgb$2$d = e_rgb$2$q;
        e_pass$2$clock = clock;
        e_pass$2$d = e_pass$2$q;
        e_live$2$clock = clock;
        e_live$2$d = e_live$2$q;
        e_zaddr$3$clock = clock;
        e_zaddr$3$d = e_zaddr$3$q;
        e_caddr$3$clock = clock;
        e_caddr$3$d = e_caddr$3$q;
        e_z$3$clock = clock;
        e_z$3$d = e_z$3$q;
        e_rgb$3$clock = clock;
        e_rgb$3$d = e_rgb$3$q;
        e_pass$3$clock = clock;
        e_pass$3$d = e_pass$3$q;
        e_live$3$clock = clock;
        e_live$3$d = e_live$3$q;
        e_zaddr$4$clock = clock;
        e_zaddr$4$d = e_zaddr$4$q;
        e_caddr$4$clock = clock;
        e_caddr$4$d = e_caddr$4$q;
        e_z$4$clock = clock;
        e_z$4$d = e_z$4$q;
        e_rgb$4$clock = clock;
        e_rgb$4$d = e_rgb$4$q;
        e_pass$4$clock = clock;
        e_pass$4$d = e_pass$4$q;
        e_live$4$clock = clock;
        e_live$4$d = e_live$4$q;
        e_zaddr$5$clock = clock;
        e_zaddr$5$d = e_zaddr$5$q;
        e_caddr$5$clock = clock;
        e_caddr$5$d = e_caddr$5$q;
        e_z$5$clock = clock;
        e_z$5$d = e_z$5$q;
        e_rgb$5$clock = clock;
        e_rgb$5$d = e_rgb$5$q;
        e_pass$5$clock = clock;
        e_pass$5$d = e_pass$5$q;
        e_live$5$clock = clock;
        e_live$5$d = e_live$5$q;
        e_zaddr$6$clock = clock;
        e_zaddr$6$d = e_zaddr$6$q;
        e_caddr$6$clock = clock;
        e_caddr$6$d = e_caddr$6$q;
        e_z$6$clock = clock;
        e_z$6$d = e_z$6$q;
        e_rgb$6$clock = clock;
        e_rgb$6$d = e_rgb$6$q;
        e_pass$6$clock = clock;
        e_pass$6$d = e_pass$6$q;
        e_live$6$clock = clock;
        e_live$6$d = e_live$6$q;
        e_zaddr$7$clock = clock;
        e_zaddr$7$d = e_zaddr$7$q;
        e_caddr$7$clock = clock;
        e_caddr$7$d = e_caddr$7$q;
        e_z$7$clock = clock;
        e_z$7$d = e_z$7$q;
        e_rgb$7$clock = clock;
        e_rgb$7$d = e_rgb$7$q;
        e_pass$7$clock = clock;
        e_pass$7$d = e_pass$7$q;
        e_live$7$clock = clock;
        e_live$7$d = e_live$7$q;
        e_zaddr$8$clock = clock;
        e_zaddr$8$d = e_zaddr$8$q;
        e_caddr$8$clock = clock;
        e_caddr$8$d = e_caddr$8$q;
        e_z$8$clock = clock;
        e_z$8$d = e_z$8$q;
        e_rgb$8$clock = clock;
        e_rgb$8$d = e_rgb$8$q;
        e_pass$8$clock = clock;
        e_pass$8$d = e_pass$8$q;
        e_live$8$clock = clock;
        e_live$8$d = e_live$8$q;
        e_zaddr$9$clock = clock;
        e_zaddr$9$d = e_zaddr$9$q;
        e_caddr$9$clock = clock;
        e_caddr$9$d = e_caddr$9$q;
        e_z$9$clock = clock;
        e_z$9$d = e_z$9$q;
        e_rgb$9$clock = clock;
        e_rgb$9$d = e_rgb$9$q;
        e_pass$9$clock = clock;
        e_pass$9$d = e_pass$9$q;
        e_live$9$clock = clock;
        e_live$9$d = e_live$9$q;
        e_zaddr$10$clock = clock;
        e_zaddr$10$d = e_zaddr$10$q;
        e_caddr$10$clock = clock;
        e_caddr$10$d = e_caddr$10$q;
        e_z$10$clock = clock;
        e_z$10$d = e_z$10$q;
        e_rgb$10$clock = clock;
        e_rgb$10$d = e_rgb$10$q;
        e_pass$10$clock = clock;
        e_pass$10$d = e_pass$10$q;
        e_live$10$clock = clock;
        e_live$10$d = e_live$10$q;
        e_zaddr$11$clock = clock;
        e_zaddr$11$d = e_zaddr$11$q;
        e_caddr$11$clock = clock;
        e_caddr$11$d = e_caddr$11$q;
        e_z$11$clock = clock;
        e_z$11$d = e_z$11$q;
        e_rgb$11$clock = clock;
        e_rgb$11$d = e_rgb$11$q;
        e_pass$11$clock = clock;
        e_pass$11$d = e_pass$11$q;
        e_live$11$clock = clock;
        e_live$11$d = e_live$11$q;
        e_zaddr$12$clock = clock;
        e_zaddr$12$d = e_zaddr$12$q;
        e_caddr$12$clock = clock;
        e_caddr$12$d = e_caddr$12$q;
        e_z$12$clock = clock;
        e_z$12$d = e_z$12$q;
        e_rgb$12$clock = clock;
        e_rgb$12$d = e_rgb$12$q;
        e_pass$12$clock = clock;
        e_pass$12$d = e_pass$12$q;
        e_live$12$clock = clock;
        e_live$12$d = e_live$12$q;
        e_zaddr$13$clock = clock;
        e_zaddr$13$d = e_zaddr$13$q;
        e_caddr$13$clock = clock;
        e_caddr$13$d = e_caddr$13$q;
        e_z$13$clock = clock;
        e_z$13$d = e_z$13$q;
        e_rgb$13$clock = clock;
        e_rgb$13$d = e_rgb$13$q;
        e_pass$13$clock = clock;
        e_pass$13$d = e_pass$13$q;
        e_live$13$clock = clock;
        e_live$13$d = e_live$13$q;
        e_zaddr$14$clock = clock;
        e_zaddr$14$d = e_zaddr$14$q;
        e_caddr$14$clock = clock;
        e_caddr$14$d = e_caddr$14$q;
        e_z$14$clock = clock;
        e_z$14$d = e_z$14$q;
        e_rgb$14$clock = clock;
        e_rgb$14$d = e_rgb$14$q;
        e_pass$14$clock = clock;
        e_pass$14$d = e_pass$14$q;
        e_live$14$clock = clock;
        e_live$14$d = e_live$14$q;
        e_zaddr$15$clock = clock;
        e_zaddr$15$d = e_zaddr$15$q;
        e_caddr$15$clock = clock;
        e_caddr$15$d = e_caddr$15$q;
        e_z$15$clock = clock;
        e_z$15$d = e_z$15$q;
        e_rgb$15$clock = clock;
        e_rgb$15$d = e_rgb$15$q;
        e_pass$15$clock = clock;
        e_pass$15$d = e_pass$15$q;
        e_live$15$clock = clock;
        e_live$15$d = e_live$15$q;
        clearing = phase$q == 32'h1;
        drawing = phase$q == 32'h0;
        idle_now = drawing & (in_head$q == in_tail$q) & (head$q == tail$q) & (z_pending$q == 32'h0) & (c_pending$q == 32'h0);
        idle = idle_now;
        error = err$q;
        y_sel = ((inp$y) & 11'h7ff);
        x4$hi = ((inp$x) & 11'h7ff);
        if (clearing) begin
            y_sel = cy$q;
            x4$hi = cx$q;
        end
        x4$lo = 32'h0;
        zmul$a = ((y_sel) & 12'hfff);
        zmul$b = ((depth_pitch) & 17'h1ffff);
        cmul$a = ((y_sel) & 12'hfff);
        cmul$b = ((color_pitch) & 17'h1ffff);
        zaddr = depth_base + zmul$p + ((x4$out) & 32'hffffffff);
        caddr = color_base + cmul$p + ((x4$out) & 32'hffffffff);
        rg$hi = inp$rgb0;
        rg$lo = inp$rgb1;
        rgb$hi = rg$out;
        rgb$lo = inp$rgb2;
        zero = 32'h0;
        far = ~zero;
        w_i = written$q[(32'h0)+:(4)];
        h_i = head$q[(32'h0)+:(4)];
        t_i = tested$q[(32'h0)+:(4)];
        tail_i = tail$q[(32'h0)+:(4)];
        in_count = in_tail$q - in_head$q;
        inp$ready = drawing & ~in_count[32'h1];
        take = inp$valid & inp$ready;
        if (take & (in_tail$q[(32'h0)+:(1)] == 0)) begin
            in_zaddr$0$d = zaddr;
            in_caddr$0$d = caddr;
            in_z$0$d = inp$z;
            in_rgb$0$d = rgb$out;
        end
        if (take & (in_tail$q[(32'h0)+:(1)] == 1)) begin
            in_zaddr$1$d = zaddr;
            in_caddr$1$d = caddr;
            in_z$1$d = inp$z;
            in_rgb$1$d = rgb$out;
        end
        if (take) begin
            in_tail$d = in_tail$q + 32'h1;
        end
        oldest_zaddr = in_zaddr$0$q;
        oldest_caddr = in_caddr$0$q;
        oldest_z = in_z$0$q;
        oldest_rgb = in_rgb$0$q;
        if (in_head$q[32'h0]) begin
            oldest_zaddr = in_zaddr$1$q;
            oldest_caddr = in_caddr$1$q;
            oldest_z = in_z$1$q;
            oldest_rgb = in_rgb$1$q;
        end
        hazard = 1'b0;
        if (e_live$0$q & (e_zaddr$0$q == oldest_zaddr)) begin
            hazard = 1'b1;
        end
        if (e_live$1$q & (e_zaddr$1$q == oldest_zaddr)) begin
            hazard = 1'b1;
        end
        if (e_live$2$q & (e_zaddr$2$q == oldest_zaddr)) begin
            hazard = 1'b1;
        end
        if (e_live$3$q & (e_zaddr$3$q == oldest_zaddr)) begin
            hazard = 1'b1;
        end
        if (e_live$4$q & (e_zaddr$4$q == oldest_zaddr)) begin
            hazard = 1'b1;
        end
        if (e_live$5$q & (e_zaddr$5$q == oldest_zaddr)) begin
            hazard = 1'b1;
        end
        if (e_live$6$q & (e_zaddr$6$q == oldest_zaddr)) begin
            hazard = 1'b1;
        end
        if (e_live$7$q & (e_zaddr$7$q == oldest_zaddr)) begin
            hazard = 1'b1;
        end
        if (e_live$8$q & (e_zaddr$8$q == oldest_zaddr)) begin
            hazard = 1'b1;
        end
        if (e_live$9$q & (e_zaddr$9$q == oldest_zaddr)) begin
            hazard = 1'b1;
        end
        if (e_live$10$q & (e_zaddr$10$q == oldest_zaddr)) begin
            hazard = 1'b1;
        end
        if (e_live$11$q & (e_zaddr$11$q == oldest_zaddr)) begin
            hazard = 1'b1;
        end
        if (e_live$12$q & (e_zaddr$12$q == oldest_zaddr)) begin
            hazard = 1'b1;
        end
        if (e_live$13$q & (e_zaddr$13$q == oldest_zaddr)) begin
            hazard = 1'b1;
        end
        if (e_live$14$q & (e_zaddr$14$q == oldest_zaddr)) begin
            hazard = 1'b1;
        end
        if (e_live$15$q & (e_zaddr$15$q == oldest_zaddr)) begin
            hazard = 1'b1;
        end
        count = tail$q - head$q;
        enter = drawing & |in_count & ~count[32'h4] & (~ar_valid$q | zr$ar_ready) & ~hazard;
        if (enter) begin
            in_head$d = in_head$q + 32'h1;
        end
        w_zaddr = e_zaddr$0$q;
        w_caddr = e_caddr$0$q;
        w_z = e_z$0$q;
        w_rgb = e_rgb$0$q;
        w_pass = e_pass$0$q;
        h_pass = e_pass$0$q;
        t_z = e_z$0$q;
        if (w_i == 1) begin
            w_zaddr = e_zaddr$1$q;
            w_caddr = e_caddr$1$q;
            w_z = e_z$1$q;
            w_rgb = e_rgb$1$q;
            w_pass = e_pass$1$q;
        end
        if (h_i == 1) begin
            h_pass = e_pass$1$q;
        end
        if (t_i == 1) begin
            t_z = e_z$1$q;
        end
        if (w_i == 2) begin
            w_zaddr = e_zaddr$2$q;
            w_caddr = e_caddr$2$q;
            w_z = e_z$2$q;
            w_rgb = e_rgb$2$q;
            w_pass = e_pass$2$q;
        end
        if (h_i == 2) begin
            h_pass = e_pass$2$q;
        end
        if (t_i == 2) begin
            t_z = e_z$2$q;
        end
        if (w_i == 3) begin
            w_zaddr = e_zaddr$3$q;
            w_caddr = e_caddr$3$q;
            w_z = e_z$3$q;
            w_rgb = e_rgb$3$q;
            w_pass = e_pass$3$q;
        end
        if (h_i == 3) begin
            h_pass = e_pass$3$q;
        end
        if (t_i == 3) begin
            t_z = e_z$3$q;
        end
        if (w_i == 4) begin
            w_zaddr = e_zaddr$4$q;
            w_caddr = e_caddr$4$q;
            w_z = e_z$4$q;
            w_rgb = e_rgb$4$q;
            w_pass = e_pass$4$q;
        end
        if (h_i == 4) begin
            h_pass = e_pass$4$q;
        end
        if (t_i == 4) begin
            t_z = e_z$4$q;
        end
        if (w_i == 5) begin
            w_zaddr = e_zaddr$5$q;
            w_caddr = e_caddr$5$q;
            w_z = e_z$5$q;
            w_rgb = e_rgb$5$q;
            w_pass = e_pass$5$q;
        end
        if (h_i == 5) begin
            h_pass = e_pass$5$q;
        end
        if (t_i == 5) begin
            t_z = e_z$5$q;
        end
        if (w_i == 6) begin
            w_zaddr = e_zaddr$6$q;
            w_caddr = e_caddr$6$q;
            w_z = e_z$6$q;
            w_rgb = e_rgb$6$q;
            w_pass = e_pass$6$q;
        end
        if (h_i == 6) begin
            h_pass = e_pass$6$q;
        end
        if (t_i == 6) begin
            t_z = e_z$6$q;
        end
        if (w_i == 7) begin
            w_zaddr = e_zaddr$7$q;
            w_caddr = e_caddr$7$q;
            w_z = e_z$7$q;
            w_rgb = e_rgb$7$q;
            w_pass = e_pass$7$q;
        end
        if (h_i == 7) begin
            h_pass = e_pass$7$q;
        end
        if (t_i == 7) begin
            t_z = e_z$7$q;
        end
        if (w_i == 8) begin
            w_zaddr = e_zaddr$8$q;
            w_caddr = e_caddr$8$q;
            w_z = e_z$8$q;
            w_rgb = e_rgb$8$q;
            w_pass = e_pass$8$q;
        end
        if (h_i == 8) begin
            h_pass = e_pass$8$q;
        end
        if (t_i == 8) begin
            t_z = e_z$8$q;
        end
        if (w_i == 9) begin
            w_zaddr = e_zaddr$9$q;
            w_caddr = e_caddr$9$q;
            w_z = e_z$9$q;
            w_rgb = e_rgb$9$q;
            w_pass = e_pass$9$q;
        end
        if (h_i == 9) begin
            h_pass = e_pass$9$q;
        end
        if (t_i == 9) begin
            t_z = e_z$9$q;
        end
        if (w_i == 10) begin
            w_zaddr = e_zaddr$10$q;
            w_caddr = e_caddr$10$q;
            w_z = e_z$10$q;
            w_rgb = e_rgb$10$q;
            w_pass = e_pass$10$q;
        end
        if (h_i == 10) begin
            h_pass = e_pass$10$q;
        end
        if (t_i == 10) begin
            t_z = e_z$10$q;
        end
        if (w_i == 11) begin
            w_zaddr = e_zaddr$11$q;
            w_caddr = e_caddr$11$q;
            w_z = e_z$11$q;
            w_rgb = e_rgb$11$q;
            w_pass = e_pass$11$q;
        end
        if (h_i == 11) begin
            h_pass = e_pass$11$q;
        end
        if (t_i == 11) begin
            t_z = e_z$11$q;
        end
        if (w_i == 12) begin
            w_zaddr = e_zaddr$12$q;
            w_caddr = e_caddr$12$q;
            w_z = e_z$12$q;
            w_rgb = e_rgb$12$q;
            w_pass = e_pass$12$q;
        end
        if (h_i == 12) begin
            h_pass = e_pass$12$q;
        end
        if (t_i == 12) begin
            t_z = e_z$12$q;
        end
        if (w_i == 13) begin
            w_zaddr = e_zaddr$13$q;
            w_caddr = e_caddr$13$q;
            w_z = e_z$13$q;
            w_rgb = e_rgb$13$q;
            w_pass = e_pass$13$q;
        end
        if (h_i == 13) begin
            h_pass = e_pass$13$q;
        end
        if (t_i == 13) begin
            t_z = e_z$13$q;
        end
        if (w_i == 14) begin
            w_zaddr = e_zaddr$14$q;
            w_caddr = e_caddr$14$q;
            w_z = e_z$14$q;
            w_rgb = e_rgb$14$q;
            w_pass = e_pass$14$q;
        end
        if (h_i == 14) begin
            h_pass = e_pass$14$q;
        end
        if (t_i == 14) begin
            t_z = e_z$14$q;
        end
        if (w_i == 15) begin
            w_zaddr = e_zaddr$15$q;
            w_caddr = e_caddr$15$q;
            w_z = e_z$15$q;
            w_rgb = e_rgb$15$q;
            w_pass = e_pass$15$q;
        end
        if (h_i == 15) begin
            h_pass = e_pass$15$q;
        end
        if (t_i == 15) begin
            t_z = e_z$15$q;
        end
        can_write = (~zaw_valid$q | zw$aw_ready) & (~zw_valid$q | zw$w_ready) & (~caw_valid$q | cw$aw_ready) & (~cw_valid$q | cw$w_ready) & ~z_pending$q[32'h7] & ~c_pending$q[32'h7];
        load = 1'b0;
        if (zw$aw_ready) begin
            zaw_valid$d = 1'b0;
        end
        if (zw$w_ready) begin
            zw_valid$d = 1'b0;
        end
        if (cw$aw_ready) begin
            caw_valid$d = 1'b0;
        end
        if (cw$w_ready) begin
            cw_valid$d = 1'b0;
        end
        if (clearing & can_write) begin
            load = 1'b1;
            zaw_addr$d = zaddr;
            zw_data$d = ((far) & 32'hffffffff);
            caw_addr$d = caddr;
            cw_data$d = ((background) & 32'hffffffff);
        end
        else if (written$q != tested$q) begin
            if (~w_pass | can_write) begin
                written$d = written$q + 32'h1;
            end
            if (w_pass & can_write) begin
                load = 1'b1;
                zaw_addr$d = w_zaddr;
                zw_data$d = ((w_z) & 32'hffffffff);
                caw_addr$d = w_caddr;
                cw_data$d = ((w_rgb) & 32'hffffffff);
            end
        end
        if (load) begin
            zaw_valid$d = 1'b1;
            zw_valid$d = 1'b1;
            caw_valid$d = 1'b1;
            cw_valid$d = 1'b1;
        end
        credit_in = credit$q;
        if (drawing & zw$b_valid) begin
            credit_in = credit$q + 32'h1;
        end
        retire = 1'b0;
        consume = 1'b0;
        if (head$q != written$q) begin
            if (~h_pass) begin
                retire = 1'b1;
            end
            else if (credit_in != 32'h0) begin
                retire = 1'b1;
                consume = 1'b1;
            end
        end
        credit$d = credit_in;
        if (consume) begin
            credit$d = credit_in - 32'h1;
        end
        if (retire) begin
            head$d = head$q + 32'h1;
        end
        old_z = zr$r_data[(32'h0)+:(16)];
        if (retire & (h_i == 0)) begin
            e_live$0$d = 1'b0;
        end
        if (zr$r_valid & (tested$q != tail$q) & (t_i == 0)) begin
            e_pass$0$d = (zr$r_resp == 32'h0) & (t_z < old_z);
        end
        if (enter & (tail_i == 0)) begin
            e_zaddr$0$d = oldest_zaddr;
            e_caddr$0$d = oldest_caddr;
            e_z$0$d = oldest_z;
            e_rgb$0$d = oldest_rgb;
            e_pass$0$d = 1'b0;
            e_live$0$d = 1'b1;
        end
        if (retire & (h_i == 1)) begin
            e_live$1$d = 1'b0;
        end
        if (zr$r_valid & (tested$q != tail$q) & (t_i == 1)) begin
            e_pass$1$d = (zr$r_resp == 32'h0) & (t_z < old_z);
        end
        if (enter & (tail_i == 1)) begin
            e_zaddr$1$d = oldest_zaddr;
            e_caddr$1$d = oldest_caddr;
            e_z$1$d = oldest_z;
            e_rgb$1$d = oldest_rgb;
            e_pass$1$d = 1'b0;
            e_live$1$d = 1'b1;
        end
        if (retire & (h_i == 2)) begin
            e_live$2$d = 1'b0;
        end
        if (zr$r_valid & (tested$q != tail$q) & (t_i == 2)) begin
            e_pass$2$d = (zr$r_resp == 32'h0) & (t_z < old_z);
        end
        if (enter & (tail_i == 2)) begin
            e_zaddr$2$d = oldest_zaddr;
            e_caddr$2$d = oldest_caddr;
            e_z$2$d = oldest_z;
            e_rgb$2$d = oldest_rgb;
            e_pass$2$d = 1'b0;
            e_live$2$d = 1'b1;
        end
        if (retire & (h_i == 3)) begin
            e_live$3$d = 1'b0;
        end
        if (zr$r_valid & (tested$q != tail$q) & (t_i == 3)) begin
            e_pass$3$d = (zr$r_resp == 32'h0) & (t_z < old_z);
        end
        if (enter & (tail_i == 3)) begin
            e_zaddr$3$d = oldest_zaddr;
            e_caddr$3$d = oldest_caddr;
            e_z$3$d = oldest_z;
            e_rgb$3$d = oldest_rgb;
            e_pass$3$d = 1'b0;
            e_live$3$d = 1'b1;
        end
        if (retire & (h_i == 4)) begin
            e_live$4$d = 1'b0;
        end
        if (zr$r_valid & (tested$q != tail$q) & (t_i == 4)) begin
            e_pass$4$d = (zr$r_resp == 32'h0) & (t_z < old_z);
        end
        if (enter & (tail_i == 4)) begin
            e_zaddr$4$d = oldest_zaddr;
            e_caddr$4$d = oldest_caddr;
            e_z$4$d = oldest_z;
            e_rgb$4$d = oldest_rgb;
            e_pass$4$d = 1'b0;
            e_live$4$d = 1'b1;
        end
        if (retire & (h_i == 5)) begin
            e_live$5$d = 1'b0;
        end
        if (zr$r_valid & (tested$q != tail$q) & (t_i == 5)) begin
            e_pass$5$d = (zr$r_resp == 32'h0) & (t_z < old_z);
        end
        if (enter & (tail_i == 5)) begin
            e_zaddr$5$d = oldest_zaddr;
            e_caddr$5$d = oldest_caddr;
            e_z$5$d = oldest_z;
            e_rgb$5$d = oldest_rgb;
            e_pass$5$d = 1'b0;
            e_live$5$d = 1'b1;
        end
        if (retire & (h_i == 6)) begin
            e_live$6$d = 1'b0;
        end
        if (zr$r_valid & (tested$q != tail$q) & (t_i == 6)) begin
            e_pass$6$d = (zr$r_resp == 32'h0) & (t_z < old_z);
        end
        if (enter & (tail_i == 6)) begin
            e_zaddr$6$d = oldest_zaddr;
            e_caddr$6$d = oldest_caddr;
            e_z$6$d = oldest_z;
            e_rgb$6$d = oldest_rgb;
            e_pass$6$d = 1'b0;
            e_live$6$d = 1'b1;
        end
        if (retire & (h_i == 7)) begin
            e_live$7$d = 1'b0;
        end
        if (zr$r_valid & (tested$q != tail$q) & (t_i == 7)) begin
            e_pass$7$d = (zr$r_resp == 32'h0) & (t_z < old_z);
        end
        if (enter & (tail_i == 7)) begin
            e_zaddr$7$d = oldest_zaddr;
            e_caddr$7$d = oldest_caddr;
            e_z$7$d = oldest_z;
            e_rgb$7$d = oldest_rgb;
            e_pass$7$d = 1'b0;
            e_live$7$d = 1'b1;
        end
        if (retire & (h_i == 8)) begin
            e_live$8$d = 1'b0;
        end
        if (zr$r_valid & (tested$q != tail$q) & (t_i == 8)) begin
            e_pass$8$d = (zr$r_resp == 32'h0) & (t_z < old_z);
        end
        if (enter & (tail_i == 8)) begin
            e_zaddr$8$d = oldest_zaddr;
            e_caddr$8$d = oldest_caddr;
            e_z$8$d = oldest_z;
            e_rgb$8$d = oldest_rgb;
            e_pass$8$d = 1'b0;
            e_live$8$d = 1'b1;
        end
        if (retire & (h_i == 9)) begin
            e_live$9$d = 1'b0;
        end
        if (zr$r_valid & (tested$q != tail$q) & (t_i == 9)) begin
            e_pass$9$d = (zr$r_resp == 32'h0) & (t_z < old_z);
        end
        if (enter & (tail_i == 9)) begin
            e_zaddr$9$d = oldest_zaddr;
            e_caddr$9$d = oldest_caddr;
            e_z$9$d = oldest_z;
            e_rgb$9$d = oldest_rgb;
            e_pass$9$d = 1'b0;
            e_live$9$d = 1'b1;
        end
        if (retire & (h_i == 10)) begin
            e_live$10$d = 1'b0;
        end
        if (zr$r_valid & (tested$q != tail$q) & (t_i == 10)) begin
            e_pass$10$d = (zr$r_resp == 32'h0) & (t_z < old_z);
        end
        if (enter & (tail_i == 10)) begin
            e_zaddr$10$d = oldest_zaddr;
            e_caddr$10$d = oldest_caddr;
            e_z$10$d = oldest_z;
            e_rgb$10$d = oldest_rgb;
            e_pass$10$d = 1'b0;
            e_live$10$d = 1'b1;
        end
        if (retire & (h_i == 11)) begin
            e_live$11$d = 1'b0;
        end
        if (zr$r_valid & (tested$q != tail$q) & (t_i == 11)) begin
            e_pass$11$d = (zr$r_resp == 32'h0) & (t_z < old_z);
        end
        if (enter & (tail_i == 11)) begin
            e_zaddr$11$d = oldest_zaddr;
            e_caddr$11$d = oldest_caddr;
            e_z$11$d = oldest_z;
            e_rgb$11$d = oldest_rgb;
            e_pass$11$d = 1'b0;
            e_live$11$d = 1'b1;
        end
        if (retire & (h_i == 12)) begin
            e_live$12$d = 1'b0;
        end
        if (zr$r_valid & (tested$q != tail$q) & (t_i == 12)) begin
            e_pass$12$d = (zr$r_resp == 32'h0) & (t_z < old_z);
        end
        if (enter & (tail_i == 12)) begin
            e_zaddr$12$d = oldest_zaddr;
            e_caddr$12$d = oldest_caddr;
            e_z$12$d = oldest_z;
            e_rgb$12$d = oldest_rgb;
            e_pass$12$d = 1'b0;
            e_live$12$d = 1'b1;
        end
        if (retire & (h_i == 13)) begin
            e_live$13$d = 1'b0;
        end
        if (zr$r_valid & (tested$q != tail$q) & (t_i == 13)) begin
            e_pass$13$d = (zr$r_resp == 32'h0) & (t_z < old_z);
        end
        if (enter & (tail_i == 13)) begin
            e_zaddr$13$d = oldest_zaddr;
            e_caddr$13$d = oldest_caddr;
            e_z$13$d = oldest_z;
            e_rgb$13$d = oldest_rgb;
            e_pass$13$d = 1'b0;
            e_live$13$d = 1'b1;
        end
        if (retire & (h_i == 14)) begin
            e_live$14$d = 1'b0;
        end
        if (zr$r_valid & (tested$q != tail$q) & (t_i == 14)) begin
            e_pass$14$d = (zr$r_resp == 32'h0) & (t_z < old_z);
        end
        if (enter & (tail_i == 14)) begin
            e_zaddr$14$d = oldest_zaddr;
            e_caddr$14$d = oldest_caddr;
            e_z$14$d = oldest_z;
            e_rgb$14$d = oldest_rgb;
            e_pass$14$d = 1'b0;
            e_live$14$d = 1'b1;
        end
        if (retire & (h_i == 15)) begin
            e_live$15$d = 1'b0;
        end
        if (zr$r_valid & (tested$q != tail$q) & (t_i == 15)) begin
            e_pass$15$d = (zr$r_resp == 32'h0) & (t_z < old_z);
        end
        if (enter & (tail_i == 15)) begin
            e_zaddr$15$d = oldest_zaddr;
            e_caddr$15$d = oldest_caddr;
            e_z$15$d = oldest_z;
            e_rgb$15$d = oldest_rgb;
            e_pass$15$d = 1'b0;
            e_live$15$d = 1'b1;
        end
        if (zr$r_valid & (tested$q != tail$q)) begin
            tested$d = tested$q + 32'h1;
        end
        if (zr$ar_ready) begin
            ar_valid$d = 1'b0;
        end
        if (enter) begin
            tail$d = tail$q + 32'h1;
            ar_valid$d = 1'b1;
            ar_addr$d = oldest_zaddr;
        end
        if (load & ~zw$b_valid) begin
            z_pending$d = z_pending$q + 32'h1;
        end
        if (~load & zw$b_valid) begin
            z_pending$d = z_pending$q - 32'h1;
        end
        if (load & ~cw$b_valid) begin
            c_pending$d = c_pending$q + 32'h1;
        end
        if (~load & cw$b_valid) begin
            c_pending$d = c_pending$q - 32'h1;
        end
        err$d = err$q | (zr$r_valid & (zr$r_resp != 32'h0)) | (zw$b_valid & (zw$b_resp != 32'h0)) | (cw$b_valid & (cw$b_resp != 32'h0));
        cx_next = cx$q + 32'h1;
        cy_next = cy$q + 32'h1;
        if (clearing & load) begin
            if (cx_next < width) begin
                cx$d = cx_next;
            end
            else begin
                cx$d = 32'h0;
                cy$d = cy_next;
                if (cy_next == height) begin
                    phase$d = 32'h2;
                end
            end
        end
        if ((phase$q == 32'h2) & (z_pending$q == 32'h0) & (c_pending$q == 32'h0)) begin
            phase$d = 32'h0;
        end
        if (start & idle_now) begin
            err$d = 1'b0;
            cx$d = 32'h0;
            cy$d = 32'h0;
            if (clear & |width & |height) begin
                phase$d = 32'h1;
            end
        end
        zr$ar_valid = ar_valid$q;
        zr$ar_addr = ar_addr$q;
        zr$ar_len = 32'h0;
        zr$ar_size = 32'h2;
        zr$ar_burst = 32'h1;
        zr$r_ready = 1'b1;
        zw$aw_valid = zaw_valid$q;
        zw$aw_addr = zaw_addr$q;
        zw$w_valid = zw_valid$q;
        zw$w_data = zw_data$q;
        cw$aw_valid = caw_valid$q;
        cw$aw_addr = caw_addr$q;
        cw$w_valid = cw_valid$q;
        cw$w_data = cw_data$q;
        zw$aw_len = 32'h0;
        zw$aw_size = 32'h2;
        zw$aw_burst = 32'h1;
        zw$w_strb = 32'hf;
        zw$w_last = 1'b1;
        zw$b_ready = 1'b1;
        cw$aw_len = 32'h0;
        cw$aw_size = 32'h2;
        cw$aw_burst = 32'h1;
        cw$w_strb = 32'hf;
        cw$w_last = 1'b1;
        cw$b_ready = 1'b1;
    end
    
endmodule // pixel_bus


module pixel_bus$ar_addr(d,q,clock);
    
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
          
endmodule // pixel_bus$ar_addr


module pixel_bus$ar_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_bus$ar_valid


module pixel_bus$c_pending(d,q,clock);
    
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
          
endmodule // pixel_bus$c_pending


module pixel_bus$caw_addr(d,q,clock);
    
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
          
endmodule // pixel_bus$caw_addr


module pixel_bus$caw_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_bus$caw_valid


module pixel_bus$cmul(a,b,p);
    
    // Module arguments
    input wire  [11:0] a;
    input wire  [16:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    // p = low 32 bits of a * b, both signed: a signed 32-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // pixel_bus$cmul


module pixel_bus$credit(d,q,clock);
    
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
          
endmodule // pixel_bus$credit


module pixel_bus$cw_data(d,q,clock);
    
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
          
endmodule // pixel_bus$cw_data


module pixel_bus$cw_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_bus$cw_valid


module pixel_bus$cx(d,q,clock);
    
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
          
endmodule // pixel_bus$cx


module pixel_bus$cy(d,q,clock);
    
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
          
endmodule // pixel_bus$cy


module pixel_bus$e_caddr$0(d,q,clock);
    
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
          
endmodule // pixel_bus$e_caddr$0


module pixel_bus$e_caddr$1(d,q,clock);
    
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
          
endmodule // pixel_bus$e_caddr$1


module pixel_bus$e_caddr$10(d,q,clock);
    
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
          
endmodule // pixel_bus$e_caddr$10


module pixel_bus$e_caddr$11(d,q,clock);
    
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
          
endmodule // pixel_bus$e_caddr$11


module pixel_bus$e_caddr$12(d,q,clock);
    
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
          
endmodule // pixel_bus$e_caddr$12


module pixel_bus$e_caddr$13(d,q,clock);
    
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
          
endmodule // pixel_bus$e_caddr$13


module pixel_bus$e_caddr$14(d,q,clock);
    
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
          
endmodule // pixel_bus$e_caddr$14


module pixel_bus$e_caddr$15(d,q,clock);
    
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
          
endmodule // pixel_bus$e_caddr$15


module pixel_bus$e_caddr$2(d,q,clock);
    
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
          
endmodule // pixel_bus$e_caddr$2


module pixel_bus$e_caddr$3(d,q,clock);
    
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
          
endmodule // pixel_bus$e_caddr$3


module pixel_bus$e_caddr$4(d,q,clock);
    
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
          
endmodule // pixel_bus$e_caddr$4


module pixel_bus$e_caddr$5(d,q,clock);
    
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
          
endmodule // pixel_bus$e_caddr$5


module pixel_bus$e_caddr$6(d,q,clock);
    
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
          
endmodule // pixel_bus$e_caddr$6


module pixel_bus$e_caddr$7(d,q,clock);
    
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
          
endmodule // pixel_bus$e_caddr$7


module pixel_bus$e_caddr$8(d,q,clock);
    
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
          
endmodule // pixel_bus$e_caddr$8


module pixel_bus$e_caddr$9(d,q,clock);
    
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
          
endmodule // pixel_bus$e_caddr$9


module pixel_bus$e_live$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_bus$e_live$0


module pixel_bus$e_live$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_bus$e_live$1


module pixel_bus$e_live$10(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_bus$e_live$10


module pixel_bus$e_live$11(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_bus$e_live$11


module pixel_bus$e_live$12(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_bus$e_live$12


module pixel_bus$e_live$13(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_bus$e_live$13


module pixel_bus$e_live$14(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_bus$e_live$14


module pixel_bus$e_live$15(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_bus$e_live$15


module pixel_bus$e_live$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_bus$e_live$2


module pixel_bus$e_live$3(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_bus$e_live$3


module pixel_bus$e_live$4(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_bus$e_live$4


module pixel_bus$e_live$5(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_bus$e_live$5


module pixel_bus$e_live$6(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_bus$e_live$6


module pixel_bus$e_live$7(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_bus$e_live$7


module pixel_bus$e_live$8(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_bus$e_live$8


module pixel_bus$e_live$9(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_bus$e_live$9


module pixel_bus$e_pass$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_bus$e_pass$0


module pixel_bus$e_pass$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_bus$e_pass$1


module pixel_bus$e_pass$10(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_bus$e_pass$10


module pixel_bus$e_pass$11(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_bus$e_pass$11


module pixel_bus$e_pass$12(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_bus$e_pass$12


module pixel_bus$e_pass$13(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_bus$e_pass$13


module pixel_bus$e_pass$14(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_bus$e_pass$14


module pixel_bus$e_pass$15(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_bus$e_pass$15


module pixel_bus$e_pass$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_bus$e_pass$2


module pixel_bus$e_pass$3(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_bus$e_pass$3


module pixel_bus$e_pass$4(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_bus$e_pass$4


module pixel_bus$e_pass$5(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_bus$e_pass$5


module pixel_bus$e_pass$6(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_bus$e_pass$6


module pixel_bus$e_pass$7(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_bus$e_pass$7


module pixel_bus$e_pass$8(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_bus$e_pass$8


module pixel_bus$e_pass$9(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_bus$e_pass$9


module pixel_bus$e_rgb$0(d,q,clock);
    
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
          
endmodule // pixel_bus$e_rgb$0


module pixel_bus$e_rgb$1(d,q,clock);
    
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
          
endmodule // pixel_bus$e_rgb$1


module pixel_bus$e_rgb$10(d,q,clock);
    
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
          
endmodule // pixel_bus$e_rgb$10


module pixel_bus$e_rgb$11(d,q,clock);
    
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
          
endmodule // pixel_bus$e_rgb$11


module pixel_bus$e_rgb$12(d,q,clock);
    
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
          
endmodule // pixel_bus$e_rgb$12


module pixel_bus$e_rgb$13(d,q,clock);
    
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
          
endmodule // pixel_bus$e_rgb$13


module pixel_bus$e_rgb$14(d,q,clock);
    
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
          
endmodule // pixel_bus$e_rgb$14


module pixel_bus$e_rgb$15(d,q,clock);
    
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
          
endmodule // pixel_bus$e_rgb$15


module pixel_bus$e_rgb$2(d,q,clock);
    
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
          
endmodule // pixel_bus$e_rgb$2


module pixel_bus$e_rgb$3(d,q,clock);
    
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
          
endmodule // pixel_bus$e_rgb$3


module pixel_bus$e_rgb$4(d,q,clock);
    
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
          
endmodule // pixel_bus$e_rgb$4


module pixel_bus$e_rgb$5(d,q,clock);
    
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
          
endmodule // pixel_bus$e_rgb$5


module pixel_bus$e_rgb$6(d,q,clock);
    
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
          
endmodule // pixel_bus$e_rgb$6


module pixel_bus$e_rgb$7(d,q,clock);
    
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
          
endmodule // pixel_bus$e_rgb$7


module pixel_bus$e_rgb$8(d,q,clock);
    
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
          
endmodule // pixel_bus$e_rgb$8


module pixel_bus$e_rgb$9(d,q,clock);
    
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
          
endmodule // pixel_bus$e_rgb$9


module pixel_bus$e_z$0(d,q,clock);
    
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
          
endmodule // pixel_bus$e_z$0


module pixel_bus$e_z$1(d,q,clock);
    
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
          
endmodule // pixel_bus$e_z$1


module pixel_bus$e_z$10(d,q,clock);
    
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
          
endmodule // pixel_bus$e_z$10


module pixel_bus$e_z$11(d,q,clock);
    
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
          
endmodule // pixel_bus$e_z$11


module pixel_bus$e_z$12(d,q,clock);
    
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
          
endmodule // pixel_bus$e_z$12


module pixel_bus$e_z$13(d,q,clock);
    
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
          
endmodule // pixel_bus$e_z$13


module pixel_bus$e_z$14(d,q,clock);
    
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
          
endmodule // pixel_bus$e_z$14


module pixel_bus$e_z$15(d,q,clock);
    
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
          
endmodule // pixel_bus$e_z$15


module pixel_bus$e_z$2(d,q,clock);
    
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
          
endmodule // pixel_bus$e_z$2


module pixel_bus$e_z$3(d,q,clock);
    
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
          
endmodule // pixel_bus$e_z$3


module pixel_bus$e_z$4(d,q,clock);
    
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
          
endmodule // pixel_bus$e_z$4


module pixel_bus$e_z$5(d,q,clock);
    
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
          
endmodule // pixel_bus$e_z$5


module pixel_bus$e_z$6(d,q,clock);
    
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
          
endmodule // pixel_bus$e_z$6


module pixel_bus$e_z$7(d,q,clock);
    
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
          
endmodule // pixel_bus$e_z$7


module pixel_bus$e_z$8(d,q,clock);
    
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
          
endmodule // pixel_bus$e_z$8


module pixel_bus$e_z$9(d,q,clock);
    
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
          
endmodule // pixel_bus$e_z$9


module pixel_bus$e_zaddr$0(d,q,clock);
    
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
          
endmodule // pixel_bus$e_zaddr$0


module pixel_bus$e_zaddr$1(d,q,clock);
    
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
          
endmodule // pixel_bus$e_zaddr$1


module pixel_bus$e_zaddr$10(d,q,clock);
    
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
          
endmodule // pixel_bus$e_zaddr$10


module pixel_bus$e_zaddr$11(d,q,clock);
    
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
          
endmodule // pixel_bus$e_zaddr$11


module pixel_bus$e_zaddr$12(d,q,clock);
    
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
          
endmodule // pixel_bus$e_zaddr$12


module pixel_bus$e_zaddr$13(d,q,clock);
    
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
          
endmodule // pixel_bus$e_zaddr$13


module pixel_bus$e_zaddr$14(d,q,clock);
    
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
          
endmodule // pixel_bus$e_zaddr$14


module pixel_bus$e_zaddr$15(d,q,clock);
    
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
          
endmodule // pixel_bus$e_zaddr$15


module pixel_bus$e_zaddr$2(d,q,clock);
    
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
          
endmodule // pixel_bus$e_zaddr$2


module pixel_bus$e_zaddr$3(d,q,clock);
    
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
          
endmodule // pixel_bus$e_zaddr$3


module pixel_bus$e_zaddr$4(d,q,clock);
    
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
          
endmodule // pixel_bus$e_zaddr$4


module pixel_bus$e_zaddr$5(d,q,clock);
    
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
          
endmodule // pixel_bus$e_zaddr$5


module pixel_bus$e_zaddr$6(d,q,clock);
    
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
          
endmodule // pixel_bus$e_zaddr$6


module pixel_bus$e_zaddr$7(d,q,clock);
    
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
          
endmodule // pixel_bus$e_zaddr$7


module pixel_bus$e_zaddr$8(d,q,clock);
    
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
          
endmodule // pixel_bus$e_zaddr$8


module pixel_bus$e_zaddr$9(d,q,clock);
    
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
          
endmodule // pixel_bus$e_zaddr$9


module pixel_bus$err(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_bus$err


module pixel_bus$head(d,q,clock);
    
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
          
endmodule // pixel_bus$head


module pixel_bus$in_caddr$0(d,q,clock);
    
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
          
endmodule // pixel_bus$in_caddr$0


module pixel_bus$in_caddr$1(d,q,clock);
    
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
          
endmodule // pixel_bus$in_caddr$1


module pixel_bus$in_head(d,q,clock);
    
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
          
endmodule // pixel_bus$in_head


module pixel_bus$in_rgb$0(d,q,clock);
    
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
          
endmodule // pixel_bus$in_rgb$0


module pixel_bus$in_rgb$1(d,q,clock);
    
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
          
endmodule // pixel_bus$in_rgb$1


module pixel_bus$in_tail(d,q,clock);
    
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
          
endmodule // pixel_bus$in_tail


module pixel_bus$in_z$0(d,q,clock);
    
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
          
endmodule // pixel_bus$in_z$0


module pixel_bus$in_z$1(d,q,clock);
    
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
          
endmodule // pixel_bus$in_z$1


module pixel_bus$in_zaddr$0(d,q,clock);
    
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
          
endmodule // pixel_bus$in_zaddr$0


module pixel_bus$in_zaddr$1(d,q,clock);
    
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
          
endmodule // pixel_bus$in_zaddr$1


module pixel_bus$phase(d,q,clock);
    
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
          
endmodule // pixel_bus$phase


module pixel_bus$rg(hi,lo,out);
    
    // Module arguments
    input wire  [7:0] hi;
    input wire  [7:0] lo;
    output reg  [15:0] out;
    
    // Constant declarations
    localparam  shift = 8'h8;
    
    // Update code
    always @(*) begin
        out = (((hi) & 16'hffff) << shift) | ((lo) & 16'hffff);
    end
    
endmodule // pixel_bus$rg


module pixel_bus$rgb(hi,lo,out);
    
    // Module arguments
    input wire  [15:0] hi;
    input wire  [7:0] lo;
    output reg  [23:0] out;
    
    // Constant declarations
    localparam  shift = 8'h8;
    
    // Update code
    always @(*) begin
        out = (((hi) & 24'hffffff) << shift) | ((lo) & 24'hffffff);
    end
    
endmodule // pixel_bus$rgb


module pixel_bus$tail(d,q,clock);
    
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
          
endmodule // pixel_bus$tail


module pixel_bus$tested(d,q,clock);
    
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
          
endmodule // pixel_bus$tested


module pixel_bus$written(d,q,clock);
    
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
          
endmodule // pixel_bus$written


module pixel_bus$x4(hi,lo,out);
    
    // Module arguments
    input wire  [10:0] hi;
    input wire  [1:0] lo;
    output reg  [12:0] out;
    
    // Constant declarations
    localparam  shift = 8'h2;
    
    // Update code
    always @(*) begin
        out = (((hi) & 13'h1fff) << shift) | ((lo) & 13'h1fff);
    end
    
endmodule // pixel_bus$x4


module pixel_bus$z_pending(d,q,clock);
    
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
          
endmodule // pixel_bus$z_pending


module pixel_bus$zaw_addr(d,q,clock);
    
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
          
endmodule // pixel_bus$zaw_addr


module pixel_bus$zaw_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_bus$zaw_valid


module pixel_bus$zmul(a,b,p);
    
    // Module arguments
    input wire  [11:0] a;
    input wire  [16:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    // p = low 32 bits of a * b, both signed: a signed 32-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // pixel_bus$zmul


module pixel_bus$zw_data(d,q,clock);
    
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
          
endmodule // pixel_bus$zw_data


module pixel_bus$zw_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_bus$zw_valid
