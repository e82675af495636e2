

module texture_address(clock,en,inp_valid,s,t,lambda,second,ws,hs,levels,base,min_linear,mag_linear,mip,wrap_s,wrap_t,inp_two_levels,out_valid,out_second,lanes,addr0,addr1,addr2,addr3,banks,alpha,beta,two_levels,frac);
    
    // Module arguments
    input wire  clock;
    input wire  en;
    input wire  inp_valid;
    input wire  [28:0] s;
    input wire  [28:0] t;
    input wire  [31:0] lambda;
    input wire  second;
    input wire  [3:0] ws;
    input wire  [3:0] hs;
    input wire  [3:0] levels;
    input wire  [25:0] base;
    input wire  min_linear;
    input wire  mag_linear;
    input wire  [1:0] mip;
    input wire  [1:0] wrap_s;
    input wire  [1:0] wrap_t;
    output reg  inp_two_levels;
    output reg  out_valid;
    output reg  out_second;
    output reg  [3:0] lanes;
    output reg  [25:0] addr0;
    output reg  [25:0] addr1;
    output reg  [25:0] addr2;
    output reg  [25:0] addr3;
    output reg  [7:0] banks;
    output reg  [7:0] alpha;
    output reg  [7:0] beta;
    output reg  two_levels;
    output reg  [5:0] frac;
    
    // Constant declarations
    localparam  bank_id$0 = 2'b0;
    localparam  bank_id$1 = 2'b1;
    localparam  bank_id$2 = 2'b10;
    localparam  bank_id$3 = 2'b11;
    localparam  lane_bit$0 = 4'h1;
    localparam  lane_bit$1 = 4'h2;
    localparam  lane_bit$2 = 4'h4;
    localparam  lane_bit$3 = 4'h8;
    localparam  pos$0 = 6'b0;
    localparam  pos$1 = 6'b1;
    localparam  pos$2 = 6'b10;
    localparam  pos$3 = 6'b11;
    localparam  pos$4 = 6'b100;
    localparam  pos$5 = 6'b101;
    localparam  pos$6 = 6'b110;
    localparam  pos$7 = 6'b111;
    localparam  pos$8 = 6'b1000;
    localparam  pos$9 = 6'b1001;
    localparam  pos$10 = 6'b1010;
    localparam  pos$11 = 6'b1011;
    localparam  pos$12 = 6'b1100;
    localparam  pos$13 = 6'b1101;
    localparam  pos$14 = 6'b1110;
    localparam  pos$15 = 6'b1111;
    localparam  pos$16 = 6'b10000;
    localparam  pos$17 = 6'b10001;
    localparam  pos$18 = 6'b10010;
    localparam  pos$19 = 6'b10011;
    localparam  pos$20 = 6'b10100;
    localparam  pos$21 = 6'b10101;
    localparam  pos$22 = 6'b10110;
    localparam  pos$23 = 6'b10111;
    localparam  pos$24 = 6'b11000;
    localparam  pos$25 = 6'b11001;
    localparam  pos_bit$0 = 26'h1;
    localparam  pos_bit$1 = 26'h2;
    localparam  pos_bit$2 = 26'h4;
    localparam  pos_bit$3 = 26'h8;
    localparam  pos_bit$4 = 26'h10;
    localparam  pos_bit$5 = 26'h20;
    localparam  pos_bit$6 = 26'h40;
    localparam  pos_bit$7 = 26'h80;
    localparam  pos_bit$8 = 26'h100;
    localparam  pos_bit$9 = 26'h200;
    localparam  pos_bit$10 = 26'h400;
    localparam  pos_bit$11 = 26'h800;
    localparam  pos_bit$12 = 26'h1000;
    localparam  pos_bit$13 = 26'h2000;
    localparam  pos_bit$14 = 26'h4000;
    localparam  pos_bit$15 = 26'h8000;
    localparam  pos_bit$16 = 26'h10000;
    localparam  pos_bit$17 = 26'h20000;
    localparam  pos_bit$18 = 26'h40000;
    localparam  pos_bit$19 = 26'h80000;
    localparam  pos_bit$20 = 26'h100000;
    localparam  pos_bit$21 = 26'h200000;
    localparam  pos_bit$22 = 26'h400000;
    localparam  pos_bit$23 = 26'h800000;
    localparam  pos_bit$24 = 26'h1000000;
    localparam  pos_bit$25 = 26'h2000000;
    
    // Stub signals
    reg  a_valid$d;
    wire  a_valid$q;
    reg  a_valid$clock;
    reg  a_second$d;
    wire  a_second$q;
    reg  a_second$clock;
    reg  [28:0] a_s$d;
    wire  [28:0] a_s$q;
    reg  a_s$clock;
    reg  [28:0] a_t$d;
    wire  [28:0] a_t$q;
    reg  a_t$clock;
    reg  a_two$d;
    wire  a_two$q;
    reg  a_two$clock;
    reg  [5:0] a_frac$d;
    wire  [5:0] a_frac$q;
    reg  a_frac$clock;
    reg  a_linear$d;
    wire  a_linear$q;
    reg  a_linear$clock;
    reg  [3:0] a_level$d;
    wire  [3:0] a_level$q;
    reg  a_level$clock;
    reg  [3:0] a_sw$d;
    wire  [3:0] a_sw$q;
    reg  a_sw$clock;
    reg  [3:0] a_sh$d;
    wire  [3:0] a_sh$q;
    reg  a_sh$clock;
    reg  [3:0] a_pw$d;
    wire  [3:0] a_pw$q;
    reg  a_pw$clock;
    reg  [3:0] a_ph$d;
    wire  [3:0] a_ph$q;
    reg  a_ph$clock;
    reg  [28:0] across$coord;
    reg  [3:0] across$size_log2;
    reg  across$linear;
    wire  [21:0] across$i0;
    wire  [21:0] across$i1;
    wire  [7:0] across$frac;
    reg  [28:0] up$coord;
    reg  [3:0] up$size_log2;
    reg  up$linear;
    wire  [21:0] up$i0;
    wire  [21:0] up$i1;
    wire  [7:0] up$frac;
    reg  b_valid$d;
    wire  b_valid$q;
    reg  b_valid$clock;
    reg  b_second$d;
    wire  b_second$q;
    reg  b_second$clock;
    reg  b_two$d;
    wire  b_two$q;
    reg  b_two$clock;
    reg  [5:0] b_frac$d;
    wire  [5:0] b_frac$q;
    reg  b_frac$clock;
    reg  [3:0] b_sw$d;
    wire  [3:0] b_sw$q;
    reg  b_sw$clock;
    reg  [3:0] b_sh$d;
    wire  [3:0] b_sh$q;
    reg  b_sh$clock;
    reg  [3:0] b_pw$d;
    wire  [3:0] b_pw$q;
    reg  b_pw$clock;
    reg  [4:0] b_pwh$d;
    wire  [4:0] b_pwh$q;
    reg  b_pwh$clock;
    reg  [21:0] b_i0$d;
    wire  [21:0] b_i0$q;
    reg  b_i0$clock;
    reg  [21:0] b_i1$d;
    wire  [21:0] b_i1$q;
    reg  b_i1$clock;
    reg  [21:0] b_j0$d;
    wire  [21:0] b_j0$q;
    reg  b_j0$clock;
    reg  [21:0] b_j1$d;
    wire  [21:0] b_j1$q;
    reg  b_j1$clock;
    reg  [7:0] b_alpha$d;
    wire  [7:0] b_alpha$q;
    reg  b_alpha$clock;
    reg  [7:0] b_beta$d;
    wire  [7:0] b_beta$q;
    reg  b_beta$clock;
    reg  [25:0] b_first$d;
    wire  [25:0] b_first$q;
    reg  b_first$clock;
    reg  [21:0] wrap$0$i;
    reg  [3:0] wrap$0$size_log2;
    reg  [1:0] wrap$0$mode;
    wire  [12:0] wrap$0$wrapped;
    reg  [21:0] wrap$1$i;
    reg  [3:0] wrap$1$size_log2;
    reg  [1:0] wrap$1$mode;
    wire  [12:0] wrap$1$wrapped;
    reg  [21:0] wrap$2$i;
    reg  [3:0] wrap$2$size_log2;
    reg  [1:0] wrap$2$mode;
    wire  [12:0] wrap$2$wrapped;
    reg  [21:0] wrap$3$i;
    reg  [3:0] wrap$3$size_log2;
    reg  [1:0] wrap$3$mode;
    wire  [12:0] wrap$3$wrapped;
    reg  [12:0] word$0$i;
    reg  [12:0] word$0$j;
    reg  [1:0] word$0$bank;
    reg  [25:0] word$0$first;
    reg  [3:0] word$0$pw;
    reg  [4:0] word$0$pwh;
    wire  [25:0] word$0$addr;
    reg  [12:0] word$1$i;
    reg  [12:0] word$1$j;
    reg  [1:0] word$1$bank;
    reg  [25:0] word$1$first;
    reg  [3:0] word$1$pw;
    reg  [4:0] word$1$pwh;
    wire  [25:0] word$1$addr;
    reg  [12:0] word$2$i;
    reg  [12:0] word$2$j;
    reg  [1:0] word$2$bank;
    reg  [25:0] word$2$first;
    reg  [3:0] word$2$pw;
    reg  [4:0] word$2$pwh;
    wire  [25:0] word$2$addr;
    reg  [12:0] word$3$i;
    reg  [12:0] word$3$j;
    reg  [1:0] word$3$bank;
    reg  [25:0] word$3$first;
    reg  [3:0] word$3$pw;
    reg  [4:0] word$3$pwh;
    wire  [25:0] word$3$addr;
    reg  c_valid$d;
    wire  c_valid$q;
    reg  c_valid$clock;
    reg  c_second$d;
    wire  c_second$q;
    reg  c_second$clock;
    reg  c_two$d;
    wire  c_two$q;
    reg  c_two$clock;
    reg  [5:0] c_frac$d;
    wire  [5:0] c_frac$q;
    reg  c_frac$clock;
    reg  [7:0] c_alpha$d;
    wire  [7:0] c_alpha$q;
    reg  c_alpha$clock;
    reg  [7:0] c_beta$d;
    wire  [7:0] c_beta$q;
    reg  c_beta$clock;
    reg  [3:0] c_lanes$d;
    wire  [3:0] c_lanes$q;
    reg  c_lanes$clock;
    reg  [7:0] c_banks$d;
    wire  [7:0] c_banks$q;
    reg  c_banks$clock;
    reg  [25:0] c_addr$0$d;
    wire  [25:0] c_addr$0$q;
    reg  c_addr$0$clock;
    reg  [25:0] c_addr$1$d;
    wire  [25:0] c_addr$1$q;
    reg  c_addr$1$clock;
    reg  [25:0] c_addr$2$d;
    wire  [25:0] c_addr$2$q;
    reg  c_addr$2$clock;
    reg  [25:0] c_addr$3$d;
    wire  [25:0] c_addr$3$q;
    reg  c_addr$3$clock;
    
    // Local signals
    reg  magnify;
    reg  [31:0] q;
    reg  [31:0] d;
    reg  [3:0] level;
    reg  [3:0] sw;
    reg  [3:0] sh;
    reg  [5:0] ws_e;
    reg  [5:0] hs_e;
    reg  [5:0] d_e;
    reg  [5:0] side_max;
    reg  [5:0] side_min;
    reg  [5:0] side_sum;
    reg  [5:0] m_lv;
    reg  [5:0] m_2;
    reg  [5:0] e_lv;
    reg  [5:0] from_sum$0;
    reg  [5:0] from_sum$1;
    reg  [5:0] from_sum$2;
    reg  [5:0] from_sum$3;
    reg  [5:0] from_sum$4;
    reg  [5:0] from_sum$5;
    reg  [5:0] from_sum$6;
    reg  [5:0] from_sum$7;
    reg  [5:0] from_sum$8;
    reg  [5:0] from_sum$9;
    reg  [5:0] from_sum$10;
    reg  [5:0] from_sum$11;
    reg  [5:0] from_sum$12;
    reg  [5:0] from_sum$13;
    reg  [5:0] from_sum$14;
    reg  [5:0] from_sum$15;
    reg  [5:0] from_sum$16;
    reg  [5:0] from_sum$17;
    reg  [5:0] from_sum$18;
    reg  [5:0] from_sum$19;
    reg  [5:0] from_sum$20;
    reg  [5:0] from_sum$21;
    reg  [5:0] from_sum$22;
    reg  [5:0] from_sum$23;
    reg  [5:0] from_sum$24;
    reg  [5:0] from_sum$25;
    reg  [5:0] from_max$0;
    reg  [5:0] from_max$1;
    reg  [5:0] from_max$2;
    reg  [5:0] from_max$3;
    reg  [5:0] from_max$4;
    reg  [5:0] from_max$5;
    reg  [5:0] from_max$6;
    reg  [5:0] from_max$7;
    reg  [5:0] from_max$8;
    reg  [5:0] from_max$9;
    reg  [5:0] from_max$10;
    reg  [5:0] from_max$11;
    reg  [5:0] from_max$12;
    reg  [5:0] from_max$13;
    reg  [5:0] from_max$14;
    reg  [5:0] from_max$15;
    reg  [5:0] from_max$16;
    reg  [5:0] from_max$17;
    reg  [5:0] from_max$18;
    reg  [5:0] from_max$19;
    reg  [5:0] from_max$20;
    reg  [5:0] from_max$21;
    reg  [5:0] from_max$22;
    reg  [5:0] from_max$23;
    reg  [5:0] from_max$24;
    reg  [5:0] from_max$25;
    reg  [25:0] runs;
    reg  [25:0] ones;
    reg  [12:0] i_even;
    reg  [12:0] i_odd;
    reg  [12:0] j_even;
    reg  [12:0] j_odd;
    reg  has_i_even;
    reg  has_i_odd;
    reg  has_j_even;
    reg  has_j_odd;
    reg  [3:0] lane;
    
    // Sub module instances
    texture_address$a_valid a_valid(
        .d(a_valid$d),
        .q(a_valid$q),
        .clock(a_valid$clock)
    );
    texture_address$a_second a_second(
        .d(a_second$d),
        .q(a_second$q),
        .clock(a_second$clock)
    );
    texture_address$a_s a_s(
        .d(a_s$d),
        .q(a_s$q),
        .clock(a_s$clock)
    );
    texture_address$a_t a_t(
        .d(a_t$d),
        .q(a_t$q),
        .clock(a_t$clock)
    );
    texture_address$a_two a_two(
        .d(a_two$d),
        .q(a_two$q),
        .clock(a_two$clock)
    );
    texture_address$a_frac a_frac(
        .d(a_frac$d),
        .q(a_frac$q),
        .clock(a_frac$clock)
    );
    texture_address$a_linear a_linear(
        .d(a_linear$d),
        .q(a_linear$q),
        .clock(a_linear$clock)
    );
    texture_address$a_level a_level(
        .d(a_level$d),
        .q(a_level$q),
        .clock(a_level$clock)
    );
    texture_address$a_sw a_sw(
        .d(a_sw$d),
        .q(a_sw$q),
        .clock(a_sw$clock)
    );
    texture_address$a_sh a_sh(
        .d(a_sh$d),
        .q(a_sh$q),
        .clock(a_sh$clock)
    );
    texture_address$a_pw a_pw(
        .d(a_pw$d),
        .q(a_pw$q),
        .clock(a_pw$clock)
    );
    texture_address$a_ph a_ph(
        .d(a_ph$d),
        .q(a_ph$q),
        .clock(a_ph$clock)
    );
    texture_address$across across(
        .coord(across$coord),
        .size_log2(across$size_log2),
        .linear(across$linear),
        .i0(across$i0),
        .i1(across$i1),
        .frac(across$frac)
    );
    texture_address$up up(
        .coord(up$coord),
        .size_log2(up$size_log2),
        .linear(up$linear),
        .i0(up$i0),
        .i1(up$i1),
        .frac(up$frac)
    );
    texture_address$b_valid b_valid(
        .d(b_valid$d),
        .q(b_valid$q),
        .clock(b_valid$clock)
    );
    texture_address$b_second b_second(
        .d(b_second$d),
        .q(b_second$q),
        .clock(b_second$clock)
    );
    texture_address$b_two b_two(
        .d(b_two$d),
        .q(b_two$q),
        .clock(b_two$clock)
    );
    texture_address$b_frac b_frac(
        .d(b_frac$d),
        .q(b_frac$q),
        .clock(b_frac$clock)
    );
    texture_address$b_sw b_sw(
        .d(b_sw$d),
        .q(b_sw$q),
        .clock(b_sw$clock)
    );
    texture_address$b_sh b_sh(
        .d(b_sh$d),
        .q(b_sh$q),
        .clock(b_sh$clock)
    );
    texture_address$b_pw b_pw(
        .d(b_pw$d),
        .q(b_pw$q),
        .clock(b_pw$clock)
    );
    texture_address$b_pwh b_pwh(
        .d(b_pwh$d),
        .q(b_pwh$q),
        .clock(b_pwh$clock)
    );
    texture_address$b_i0 b_i0(
        .d(b_i0$d),
        .q(b_i0$q),
        .clock(b_i0$clock)
    );
    texture_address$b_i1 b_i1(
        .d(b_i1$d),
        .q(b_i1$q),
        .clock(b_i1$clock)
    );
    texture_address$b_j0 b_j0(
        .d(b_j0$d),
        .q(b_j0$q),
        .clock(b_j0$clock)
    );
    texture_address$b_j1 b_j1(
        .d(b_j1$d),
        .q(b_j1$q),
        .clock(b_j1$clock)
    );
    texture_address$b_alpha b_alpha(
        .d(b_alpha$d),
        .q(b_alpha$q),
        .clock(b_alpha$clock)
    );
    texture_address$b_beta b_beta(
        .d(b_beta$d),
        .q(b_beta$q),
        .clock(b_beta$clock)
    );
    texture_address$b_first b_first(
        .d(b_first$d),
        .q(b_first$q),
        .clock(b_first$clock)
    );
    texture_address$wrap$0 wrap$0(
        .i(wrap$0$i),
        .size_log2(wrap$0$size_log2),
        .mode(wrap$0$mode),
        .wrapped(wrap$0$wrapped)
    );
    texture_address$wrap$1 wrap$1(
        .i(wrap$1$i),
        .size_log2(wrap$1$size_log2),
        .mode(wrap$1$mode),
        .wrapped(wrap$1$wrapped)
    );
    texture_address$wrap$2 wrap$2(
        .i(wrap$2$i),
        .size_log2(wrap$2$size_log2),
        .mode(wrap$2$mode),
        .wrapped(wrap$2$wrapped)
    );
    texture_address$wrap$3 wrap$3(
        .i(wrap$3$i),
        .size_log2(wrap$3$size_log2),
        .mode(wrap$3$mode),
        .wrapped(wrap$3$wrapped)
    );
    texture_address$word$0 word$0(
        .i(word$0$i),
        .j(word$0$j),
        .bank(word$0$bank),
        .first(word$0$first),
        .pw(word$0$pw),
        .pwh(word$0$pwh),
        .addr(word$0$addr)
    );
    texture_address$word$1 word$1(
        .i(word$1$i),
        .j(word$1$j),
        .bank(word$1$bank),
        .first(word$1$first),
        .pw(word$1$pw),
        .pwh(word$1$pwh),
        .addr(word$1$addr)
    );
    texture_address$word$2 word$2(
        .i(word$2$i),
        .j(word$2$j),
        .bank(word$2$bank),
        .first(word$2$first),
        .pw(word$2$pw),
        .pwh(word$2$pwh),
        .addr(word$2$addr)
    );
    texture_address$word$3 word$3(
        .i(word$3$i),
        .j(word$3$j),
        .bank(word$3$bank),
        .first(word$3$first),
        .pw(word$3$pw),
        .pwh(word$3$pwh),
        .addr(word$3$addr)
    );
    texture_address$c_valid c_valid(
        .d(c_valid$d),
        .q(c_valid$q),
        .clock(c_valid$clock)
    );
    texture_address$c_second c_second(
        .d(c_second$d),
        .q(c_second$q),
        .clock(c_second$clock)
    );
    texture_address$c_two c_two(
        .d(c_two$d),
        .q(c_two$q),
        .clock(c_two$clock)
    );
    texture_address$c_frac c_frac(
        .d(c_frac$d),
        .q(c_frac$q),
        .clock(c_frac$clock)
    );
    texture_address$c_alpha c_alpha(
        .d(c_alpha$d),
        .q(c_alpha$q),
        .clock(c_alpha$clock)
    );
    texture_address$c_beta c_beta(
        .d(c_beta$d),
        .q(c_beta$q),
        .clock(c_beta$clock)
    );
    texture_address$c_lanes c_lanes(
        .d(c_lanes$d),
        .q(c_lanes$q),
        .clock(c_lanes$clock)
    );
    texture_address$c_banks c_banks(
        .d(c_banks$d),
        .q(c_banks$q),
        .clock(c_banks$clock)
    );
    texture_address$c_addr$0 c_addr$0(
        .d(c_addr$0$d),
        .q(c_addr$0$q),
        .clock(c_addr$0$clock)
    );
    texture_address$c_addr$1 c_addr$1(
        .d(c_addr$1$d),
        .q(c_addr$1$q),
        .clock(c_addr$1$clock)
    );
    texture_address$c_addr$2 c_addr$2(
        .d(c_addr$2$d),
        .q(c_addr$2$q),
        .clock(c_addr$2$clock)
    );
    texture_address$c_addr$3 c_addr$3(
        .d(c_addr$3$d),
        .q(c_addr$3$q),
        .clock(c_addr$3$clock)
    );
    
    // Update code
    always @(*) begin
        a_valid$clock = clock;
        a_second$clock = clock;
        a_s$clock = clock;
        a_t$clock = clock;
        a_two$clock = clock;
        a_frac$clock = clock;
        a_linear$clock = clock;
        a_level$clock = clock;
        a_sw$clock = clock;
        a_sh$clock = clock;
        a_pw$clock = clock;
        a_ph$clock = clock;
        b_valid$clock = clock;
        b_second$clock = clock;
        b_two$clock = clock;
        b_frac$clock = clock;
        b_sw$clock = clock;
        b_sh$clock = clock;
        b_pw$clock = clock;
        b_pwh$clock = clock;
        b_i0$clock = clock;
        b_i1$clock = clock;
        b_j0$clock = clock;
        b_j1$clock = clock;
        b_alpha$clock = clock;
        b_beta$clock = clock;
        b_first$clock = clock;
        c_valid$clock = clock;
        c_second$clock = clock;
        c_two$clock = clock;
        c_frac$clock = clock;
        c_alpha$clock = clock;
        c_beta$clock = clock;
        c_lanes$clock = clock;
        c_banks$clock = clock;
        a_valid$d = a_valid$q;
        a_second$d = a_second$q;
        a_s$d = a_s$q;
        a_t$d = a_t$q;
        a_two$d = a_two$q;
        a_frac$d = a_frac$q;
        a_linear$d = a_linear$q;
        a_level$d = a_level$q;
        a_sw$d = a_sw$q;
        a_sh$d = a_sh$q;
        a_pw$d = a_pw$q;
        a_ph$d = a_ph$q;
        b_valid$d = b_valid$q;
        b_second$d = b_second$q;
        b_two$d = b_two$q;
        b_frac$d = b_frac$q;
        b_sw$d = b_sw$q;
        b_sh$d = b_sh$q;
        b_pw$d = b_pw$q;
        b_pwh$d = b_pwh$q;
        b_i0$d = b_i0$q;
        b_i1$d = b_i1$q;
        b_j0$d = b_j0$q;
        b_j1$d = b_j1$q;
        b_alpha$d = b_alpha$q;
        b_beta$d = b_beta$q;
        b_first$d = b_first$q;
        c_valid$d = c_valid$q;
        c_second$d = c_second$q;
        c_two$d = c_two$q;
        c_frac$d = c_frac$q;
        c_alpha$d = c_alpha$q;
        c_beta$d = c_beta$q;
        c_lanes$d = c_lanes$q;
        c_banks$d = c_banks$q;
        c_addr$0$clock = clock;
        c_addr$0$d = c_addr$0$q;
        c_addr$1$clock = clock;
        c_addr$1$d = c_addr$1$q;
        c_addr$2$clock = clock;
        c_addr$2$d = c_addr$2$q;
        c_addr$3$clock = clock;
        c_addr$3$d = c_addr$3$q;
        q = ((levels) & 32'hffffffff) - 32'h1;
        magnify = lambda[32'h1f] | ~|lambda;
        inp_two_levels = 1'b0;
        d = 32'h0;
        if (~magnify) begin
            if (mip == 32'h1) begin
                d = (lambda + 32'h1f) >> 32'h6;
                if (d > q) begin
                    d = q;
                end
            end
            if (mip == 32'h2) begin
                d = lambda >> 32'h6;
                if (d >= q) begin
                    d = q;
                end
                else begin
                    inp_two_levels = 1'b1;
                    if (second) begin
                        d = d + 32'h1;
                    end
                end
            end
        end
        level = d[(32'h0)+:(4)];
        sw = 32'h0;
        if (ws > level) begin
            sw = ws - level;
        end
        sh = 32'h0;
        if (hs > level) begin
            sh = hs - level;
        end
        if (en) begin
            a_valid$d = inp_valid;
            a_second$d = second;
            a_s$d = s;
            a_t$d = t;
            a_two$d = inp_two_levels;
            a_frac$d = 32'h0;
            if (inp_two_levels) begin
                a_frac$d = lambda[(32'h0)+:(6)];
            end
            a_linear$d = min_linear;
            if (magnify) begin
                a_linear$d = mag_linear;
            end
            a_level$d = level;
            a_sw$d = sw;
            a_sh$d = sh;
            a_pw$d = 32'h0;
            if (|sw) begin
                a_pw$d = sw - 32'h1;
            end
            a_ph$d = 32'h0;
            if (|sh) begin
                a_ph$d = sh - 32'h1;
            end
        end
        across$coord = a_s$q;
        across$size_log2 = a_sw$q;
        across$linear = a_linear$q;
        up$coord = a_t$q;
        up$size_log2 = a_sh$q;
        up$linear = a_linear$q;
        ws_e = ((ws) & 6'h3f);
        hs_e = ((hs) & 6'h3f);
        d_e = ((a_level$q) & 6'h3f);
        side_max = ws_e;
        side_min = hs_e;
        if (hs_e > ws_e) begin
            side_max = hs_e;
            side_min = ws_e;
        end
        side_sum = ws_e + hs_e;
        m_lv = d_e;
        if (d_e > side_min) begin
            m_lv = side_min;
        end
        m_2 = m_lv << 32'h1;
        e_lv = d_e;
        if (d_e > side_max) begin
            e_lv = side_max;
        end
        runs = 32'h0;
        from_sum$0 = side_sum - pos$0;
        from_max$0 = side_max + 32'h1 - pos$0;
        if (~from_sum$0[32'h0] & (from_sum$0 < m_2)) begin
            runs = runs | pos_bit$0;
        end
        if ((from_max$0 >= side_min) & (from_max$0 < e_lv)) begin
            runs = runs | pos_bit$0;
        end
        from_sum$1 = side_sum - pos$1;
        from_max$1 = side_max + 32'h1 - pos$1;
        if (~from_sum$1[32'h0] & (from_sum$1 < m_2)) begin
            runs = runs | pos_bit$1;
        end
        if ((from_max$1 >= side_min) & (from_max$1 < e_lv)) begin
            runs = runs | pos_bit$1;
        end
        from_sum$2 = side_sum - pos$2;
        from_max$2 = side_max + 32'h1 - pos$2;
        if (~from_sum$2[32'h0] & (from_sum$2 < m_2)) begin
            runs = runs | pos_bit$2;
        end
        if ((from_max$2 >= side_min) & (from_max$2 < e_lv)) begin
            runs = runs | pos_bit$2;
        end
        from_sum$3 = side_sum - pos$3;
        from_max$3 = side_max + 32'h1 - pos$3;
        if (~from_sum$3[32'h0] & (from_sum$3 < m_2)) begin
            runs = runs | pos_bit$3;
        end
        if ((from_max$3 >= side_min) & (from_max$3 < e_lv)) begin
            runs = runs | pos_bit$3;
        end
        from_sum$4 = side_sum - pos$4;
        from_max$4 = side_max + 32'h1 - pos$4;
        if (~from_sum$4[32'h0] & (from_sum$4 < m_2)) begin
            runs = runs | pos_bit$4;
        end
        if ((from_max$4 >= side_min) & (from_max$4 < e_lv)) begin
            runs = runs | pos_bit$4;
        end
        from_sum$5 = side_sum - pos$5;
        from_max$5 = side_max + 32'h1 - pos$5;
        if (~from_sum$5[32'h0] & (from_sum$5 < m_2)) begin
            runs = runs | pos_bit$5;
        end
        if ((from_max$5 >= side_min) & (from_max$5 < e_lv)) begin
            runs = runs | pos_bit$5;
        end
        from_sum$6 = side_sum - pos$6;
        from_max$6 = side_max + 32'h1 - pos$6;
        if (~from_sum$6[32'h0] & (from_sum$6 < m_2)) begin
            runs = runs | pos_bit$6;
        end
        if ((from_max$6 >= side_min) & (from_max$6 < e_lv)) begin
            runs = runs | pos_bit$6;
        end
        from_sum$7 = side_sum - pos$7;
        from_max$7 = side_max + 32'h1 - pos$7;
        if (~from_sum$7[32'h0] & (from_sum$7 < m_2)) begin
            runs = runs | pos_bit$7;
        end
        if ((from_max$7 >= side_min) & (from_max$7 < e_lv)) begin
            runs = runs | pos_bit$7;
        end
        from_sum$8 = side_sum - pos$8;
        from_max$8 = side_max + 32'h1 - pos$8;
        if (~from_sum$8[32'h0] & (from_sum$8 < m_2)) begin
            runs = runs | pos_bit$8;
        end
        if ((from_max$8 >= side_min) & (from_max$8 < e_lv)) begin
            runs = runs | pos_bit$8;
        end
        from_sum$9 = side_sum - pos$9;
        from_max$9 = side_max + 32'h1 - pos$9;
        if (~from_sum$9[32'h0] & (from_sum$9 < m_2)) begin
            runs = runs | pos_bit$9;
        end
        if ((from_max$9 >= side_min) & (from_max$9 < e_lv)) begin
            runs = runs | pos_bit$9;
        end
        from_sum$10 = side_sum - pos$10;
        from_max$10 = side_max + 32'h1 - pos$10;
        if (~from_sum$10[32'h0] & (from_sum$10 < m_2)) begin
            runs = runs | pos_bit$10;
        end
        if ((from_max$10 >= side_min) & (from_max$10 < e_lv)) begin
            runs = runs | pos_bit$10;
        end
        from_sum$11 = side_sum - pos$11;
        from_max$11 = side_max + 32'h1 - pos$11;
        if (~from_sum$11[32'h0] & (from_sum$11 < m_2)) begin
            runs = runs | pos_bit$11;
        end
        if ((from_max$11 >= side_min) & (from_max$11 < e_lv)) begin
            runs = runs | pos_bit$11;
        end
        from_sum$12 = side_sum - pos$12;
        from_max$12 = side_max + 32'h1 - pos$12;
        if (~from_sum$12[32'h0] & (from_sum$12 < m_2)) begin
            runs = runs | pos_bit$12;
        end
        if ((from_max$12 >= side_min) & (from_max$12 < e_lv)) begin
            runs = runs | pos_bit$12;
        end
        from_sum$13 = side_sum - pos$13;
        from_max$13 = side_max + 32'h1 - pos$13;
        if (~from_sum$13[32'h0] & (from_sum$13 < m_2)) begin
            runs = runs | pos_bit$13;
        end
        if ((from_max$13 >= side_min) & (from_max$13 < e_lv)) begin
            runs = runs | pos_bit$13;
        end
        from_sum$14 = side_sum - pos$14;
        from_max$14 = side_max + 32'h1 - pos$14;
        if (~from_sum$14[32'h0] & (from_sum$14 < m_2)) begin
            runs = runs | pos_bit$14;
        end
        if ((from_max$14 >= side_min) & (from_max$14 < e_lv)) begin
            runs = runs | pos_bit$14;
        end
        from_sum$15 = side_sum - pos$15;
        from_max$15 = side_max + 32'h1 - pos$15;
        if (~from_sum$15[32'h0] & (from_sum$15 < m_2)) begin
            runs = runs | pos_bit$15;
        end
        if ((from_max$15 >= side_min) & (from_max$15 < e_lv)) begin
            runs = runs | pos_bit$15;
        end
        from_sum$16 = side_sum - pos$16;
        from_max$16 = side_max + 32'h1 - pos$16;
        if (~from_sum$16[32'h0] & (from_sum$16 < m_2)) begin
            runs = runs | pos_bit$16;
        end
        if ((from_max$16 >= side_min) & (from_max$16 < e_lv)) begin
            runs = runs | pos_bit$16;
        end
        from_sum$17 = side_sum - pos$17;
        from_max$17 = side_max + 32'h1 - pos$17;
        if (~from_sum$17[32'h0] & (from_sum$17 < m_2)) begin
            runs = runs | pos_bit$17;
        end
        if ((from_max$17 >= side_min) & (from_max$17 < e_lv)) begin
            runs = runs | pos_bit$17;
        end
        from_sum$18 = side_sum - pos$18;
        from_max$18 = side_max + 32'h1 - pos$18;
        if (~from_sum$18[32'h0] & (from_sum$18 < m_2)) begin
            runs = runs | pos_bit$18;
        end
        if ((from_max$18 >= side_min) & (from_max$18 < e_lv)) begin
            runs = runs | pos_bit$18;
        end
        from_sum$19 = side_sum - pos$19;
        from_max$19 = side_max + 32'h1 - pos$19;
        if (~from_sum$19[32'h0] & (from_sum$19 < m_2)) begin
            runs = runs | pos_bit$19;
        end
        if ((from_max$19 >= side_min) & (from_max$19 < e_lv)) begin
            runs = runs | pos_bit$19;
        end
        from_sum$20 = side_sum - pos$20;
        from_max$20 = side_max + 32'h1 - pos$20;
        if (~from_sum$20[32'h0] & (from_sum$20 < m_2)) begin
            runs = runs | pos_bit$20;
        end
        if ((from_max$20 >= side_min) & (from_max$20 < e_lv)) begin
            runs = runs | pos_bit$20;
        end
        from_sum$21 = side_sum - pos$21;
        from_max$21 = side_max + 32'h1 - pos$21;
        if (~from_sum$21[32'h0] & (from_sum$21 < m_2)) begin
            runs = runs | pos_bit$21;
        end
        if ((from_max$21 >= side_min) & (from_max$21 < e_lv)) begin
            runs = runs | pos_bit$21;
        end
        from_sum$22 = side_sum - pos$22;
        from_max$22 = side_max + 32'h1 - pos$22;
        if (~from_sum$22[32'h0] & (from_sum$22 < m_2)) begin
            runs = runs | pos_bit$22;
        end
        if ((from_max$22 >= side_min) & (from_max$22 < e_lv)) begin
            runs = runs | pos_bit$22;
        end
        from_sum$23 = side_sum - pos$23;
        from_max$23 = side_max + 32'h1 - pos$23;
        if (~from_sum$23[32'h0] & (from_sum$23 < m_2)) begin
            runs = runs | pos_bit$23;
        end
        if ((from_max$23 >= side_min) & (from_max$23 < e_lv)) begin
            runs = runs | pos_bit$23;
        end
        from_sum$24 = side_sum - pos$24;
        from_max$24 = side_max + 32'h1 - pos$24;
        if (~from_sum$24[32'h0] & (from_sum$24 < m_2)) begin
            runs = runs | pos_bit$24;
        end
        if ((from_max$24 >= side_min) & (from_max$24 < e_lv)) begin
            runs = runs | pos_bit$24;
        end
        from_sum$25 = side_sum - pos$25;
        from_max$25 = side_max + 32'h1 - pos$25;
        if (~from_sum$25[32'h0] & (from_sum$25 < m_2)) begin
            runs = runs | pos_bit$25;
        end
        if ((from_max$25 >= side_min) & (from_max$25 < e_lv)) begin
            runs = runs | pos_bit$25;
        end
        ones = 32'h0;
        if (d_e > side_max) begin
            ones = ((d_e - side_max) & 26'h3ffffff) << 32'h2;
        end
        if (en) begin
            b_valid$d = a_valid$q;
            b_second$d = a_second$q;
            b_two$d = a_two$q;
            b_frac$d = a_frac$q;
            b_sw$d = a_sw$q;
            b_sh$d = a_sh$q;
            b_pw$d = a_pw$q;
            b_pwh$d = ((a_pw$q) & 5'h1f) + ((a_ph$q) & 5'h1f);
            b_i0$d = across$i0;
            b_i1$d = across$i1;
            b_j0$d = up$i0;
            b_j1$d = up$i1;
            b_alpha$d = across$frac;
            b_beta$d = up$frac;
            b_first$d = base + runs + ones;
        end
        wrap$0$i = b_i0$q;
        wrap$1$i = b_i1$q;
        wrap$2$i = b_j0$q;
        wrap$3$i = b_j1$q;
        wrap$0$size_log2 = b_sw$q;
        wrap$1$size_log2 = b_sw$q;
        wrap$2$size_log2 = b_sh$q;
        wrap$3$size_log2 = b_sh$q;
        wrap$0$mode = wrap_s;
        wrap$1$mode = wrap_s;
        wrap$2$mode = wrap_t;
        wrap$3$mode = wrap_t;
        i_even = wrap$1$wrapped;
        i_odd = wrap$0$wrapped;
        if (~wrap$0$wrapped[32'h0]) begin
            i_even = wrap$0$wrapped;
            i_odd = wrap$1$wrapped;
        end
        j_even = wrap$3$wrapped;
        j_odd = wrap$2$wrapped;
        if (~wrap$2$wrapped[32'h0]) begin
            j_even = wrap$2$wrapped;
            j_odd = wrap$3$wrapped;
        end
        has_i_even = ~wrap$0$wrapped[32'h0] | ~wrap$1$wrapped[32'h0];
        has_i_odd = wrap$0$wrapped[32'h0] | wrap$1$wrapped[32'h0];
        has_j_even = ~wrap$2$wrapped[32'h0] | ~wrap$3$wrapped[32'h0];
        has_j_odd = wrap$2$wrapped[32'h0] | wrap$3$wrapped[32'h0];
        word$0$i = i_even;
        word$1$i = i_odd;
        word$2$i = i_even;
        word$3$i = i_odd;
        word$0$j = j_even;
        word$1$j = j_even;
        word$2$j = j_odd;
        word$3$j = j_odd;
        lane = 32'h0;
        if (has_i_even & has_j_even) begin
            lane = lane | lane_bit$0;
        end
        if (has_i_odd & has_j_even) begin
            lane = lane | lane_bit$1;
        end
        if (has_i_even & has_j_odd) begin
            lane = lane | lane_bit$2;
        end
        if (has_i_odd & has_j_odd) begin
            lane = lane | lane_bit$3;
        end
        word$0$bank = bank_id$0;
        word$0$first = b_first$q;
        word$0$pw = b_pw$q;
        word$0$pwh = b_pwh$q;
        word$1$bank = bank_id$1;
        word$1$first = b_first$q;
        word$1$pw = b_pw$q;
        word$1$pwh = b_pwh$q;
        word$2$bank = bank_id$2;
        word$2$first = b_first$q;
        word$2$pw = b_pw$q;
        word$2$pwh = b_pwh$q;
        word$3$bank = bank_id$3;
        word$3$first = b_first$q;
        word$3$pw = b_pw$q;
        word$3$pwh = b_pwh$q;
        if (en) begin
            c_valid$d = b_valid$q;
            c_second$d = b_second$q;
            c_two$d = b_two$q;
            c_frac$d = b_frac$q;
            c_alpha$d = b_alpha$q;
            c_beta$d = b_beta$q;
            c_banks$d = ((wrap$0$wrapped[(32'h0)+:(1)]) & 8'hff) | (((wrap$2$wrapped[(32'h0)+:(1)]) & 8'hff) << 32'h1) | (((wrap$1$wrapped[(32'h0)+:(1)]) & 8'hff) << 32'h2) | (((wrap$2$wrapped[(32'h0)+:(1)]) & 8'hff) << 32'h3) | (((wrap$0$wrapped[(32'h0)+:(1)]) & 8'hff) << 32'h4) | (((wrap$3$wrapped[(32'h0)+:(1)]) & 8'hff) << 32'h5) | (((wrap$1$wrapped[(32'h0)+:(1)]) & 8'hff) << 32'h6) | (((wrap$3$wrapped[(32'h0)+:(1)]) & 8'hff) << 32'h7);
            c_lanes$d = lane;
            c_addr$0$d = 32'h0;
            if (|(lane & lane_bit$0)) begin
                c_addr$0$d = word$0$addr;
            end
            c_addr$1$d = 32'h0;
            if (|(lane & lane_bit$1)) begin
                c_addr$1$d = word$1$addr;
            end
            c_addr$2$d = 32'h0;
            if (|(lane & lane_bit$2)) begin
                c_addr$2$d = word$2$addr;
            end
            c_addr$3$d = 32'h0;
            if (|(lane & lane_bit$3)) begin
                c_addr$3$d = word$3$addr;
            end
        end
        out_valid = c_valid$q;
        out_second = c_second$q;
        two_levels = c_two$q;
        frac = c_frac$q;
        alpha = c_alpha$q;
        beta = c_beta$q;
        lanes = c_lanes$q;
        banks = c_banks$q;
        addr0 = c_addr$0$q;
        addr1 = c_addr$1$q;
        addr2 = c_addr$2$q;
        addr3 = c_addr$3$q;
    end
    
endmodule // texture_address


module texture_address$a_frac(d,q,clock);
    
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
          
endmodule // texture_address$a_frac


module texture_address$a_level(d,q,clock);
    
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
          
endmodule // texture_address$a_level


module texture_address$a_linear(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_address$a_linear


module texture_address$a_ph(d,q,clock);
    
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
          
endmodule // texture_address$a_ph


module texture_address$a_pw(d,q,clock);
    
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
          
endmodule // texture_address$a_pw


module texture_address$a_s(d,q,clock);
    
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
          
endmodule // texture_address$a_s


module texture_address$a_second(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_address$a_second


module texture_address$a_sh(d,q,clock);
    
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
          
endmodule // texture_address$a_sh


module texture_address$a_sw(d,q,clock);
    
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
          
endmodule // texture_address$a_sw


module texture_address$a_t(d,q,clock);
    
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
          
endmodule // texture_address$a_t


module texture_address$a_two(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_address$a_two


module texture_address$a_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_address$a_valid


module texture_address$across(coord,size_log2,linear,i0,i1,frac);
    
    // Module arguments
    input wire  [28:0] coord;
    input wire  [3:0] size_log2;
    input wire  linear;
    output reg  [21:0] i0;
    output reg  [21:0] i1;
    output reg  [7:0] frac;
    
    // Local signals
    reg  [29:0] wide;
    reg  [29:0] u;
    reg  [21:0] top;
    
    // Update code
    always @(*) begin
        wide = ((coord) & 30'h3fffffff);
        if (coord[32'h1c]) begin
            wide = ((coord) & 30'h3fffffff) | ((32'h20000000) & 30'h3fffffff);
        end
        u = wide >> (((32'hc) & 30'h3fffffff) - ((size_log2) & 30'h3fffffff));
        if (coord[32'h1c]) begin
            u = (wide >> (((32'hc) & 30'h3fffffff) - ((size_log2) & 30'h3fffffff))) | ~(((32'h3fffffff) & 30'h3fffffff) >> (((32'hc) & 30'h3fffffff) - ((size_log2) & 30'h3fffffff)));
        end
        top = u[(32'h8)+:(22)];
        i0 = top;
        i1 = top;
        frac = 32'h0;
        if (linear) begin
            i1 = top + 32'h1;
            if (~u[32'h7]) begin
                i0 = top - 32'h1;
                i1 = top;
            end
            frac = u[(32'h0)+:(8)] ^ ((32'h80) & 8'hff);
        end
    end
    
endmodule // texture_address$across


module texture_address$b_alpha(d,q,clock);
    
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
          
endmodule // texture_address$b_alpha


module texture_address$b_beta(d,q,clock);
    
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
          
endmodule // texture_address$b_beta


module texture_address$b_first(d,q,clock);
    
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
          
endmodule // texture_address$b_first


module texture_address$b_frac(d,q,clock);
    
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
          
endmodule // texture_address$b_frac


module texture_address$b_i0(d,q,clock);
    
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
          
endmodule // texture_address$b_i0


module texture_address$b_i1(d,q,clock);
    
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
          
endmodule // texture_address$b_i1


module texture_address$b_j0(d,q,clock);
    
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
          
endmodule // texture_address$b_j0


module texture_address$b_j1(d,q,clock);
    
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
          
endmodule // texture_address$b_j1


module texture_address$b_pw(d,q,clock);
    
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
          
endmodule // texture_address$b_pw


module texture_address$b_pwh(d,q,clock);
    
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
          
endmodule // texture_address$b_pwh


module texture_address$b_second(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_address$b_second


module texture_address$b_sh(d,q,clock);
    
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
          
endmodule // texture_address$b_sh


module texture_address$b_sw(d,q,clock);
    
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
          
endmodule // texture_address$b_sw


module texture_address$b_two(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_address$b_two


module texture_address$b_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_address$b_valid


module texture_address$c_addr$0(d,q,clock);
    
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
          
endmodule // texture_address$c_addr$0


module texture_address$c_addr$1(d,q,clock);
    
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
          
endmodule // texture_address$c_addr$1


module texture_address$c_addr$2(d,q,clock);
    
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
          
endmodule // texture_address$c_addr$2


module texture_address$c_addr$3(d,q,clock);
    
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
          
endmodule // texture_address$c_addr$3


module texture_address$c_alpha(d,q,clock);
    
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
          
endmodule // texture_address$c_alpha


module texture_address$c_banks(d,q,clock);
    
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
          
endmodule // texture_address$c_banks


module texture_address$c_beta(d,q,clock);
    
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
          
endmodule // texture_address$c_beta


module texture_address$c_frac(d,q,clock);
    
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
          
endmodule // texture_address$c_frac


module texture_address$c_lanes(d,q,clock);
    
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
          
endmodule // texture_address$c_lanes


module texture_address$c_second(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_address$c_second


module texture_address$c_two(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_address$c_two


module texture_address$c_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_address$c_valid


module texture_address$up(coord,size_log2,linear,i0,i1,frac);
    
    // Module arguments
    input wire  [28:0] coord;
    input wire  [3:0] size_log2;
    input wire  linear;
    output reg  [21:0] i0;
    output reg  [21:0] i1;
    output reg  [7:0] frac;
    
    // Local signals
    reg  [29:0] wide;
    reg  [29:0] u;
    reg  [21:0] top;
    
    // Update code
    always @(*) begin
        wide = ((coord) & 30'h3fffffff);
        if (coord[32'h1c]) begin
            wide = ((coord) & 30'h3fffffff) | ((32'h20000000) & 30'h3fffffff);
        end
        u = wide >> (((32'hc) & 30'h3fffffff) - ((size_log2) & 30'h3fffffff));
        if (coord[32'h1c]) begin
            u = (wide >> (((32'hc) & 30'h3fffffff) - ((size_log2) & 30'h3fffffff))) | ~(((32'h3fffffff) & 30'h3fffffff) >> (((32'hc) & 30'h3fffffff) - ((size_log2) & 30'h3fffffff)));
        end
        top = u[(32'h8)+:(22)];
        i0 = top;
        i1 = top;
        frac = 32'h0;
        if (linear) begin
            i1 = top + 32'h1;
            if (~u[32'h7]) begin
                i0 = top - 32'h1;
                i1 = top;
            end
            frac = u[(32'h0)+:(8)] ^ ((32'h80) & 8'hff);
        end
    end
    
endmodule // texture_address$up


module texture_address$word$0(i,j,bank,first,pw,pwh,addr);
    
    // Module arguments
    input wire  [12:0] i;
    input wire  [12:0] j;
    input wire  [1:0] bank;
    input wire  [25:0] first;
    input wire  [3:0] pw;
    input wire  [4:0] pwh;
    output reg  [25:0] addr;
    
    // Local signals
    reg  [25:0] field;
    
    // Update code
    always @(*) begin
        field = (((bank) & 26'h3ffffff) << ((pwh) & 26'h3ffffff)) | (((j >> 32'h1) & 26'h3ffffff) << ((pw) & 26'h3ffffff)) | ((i >> 32'h1) & 26'h3ffffff);
        addr = first + field;
    end
    
endmodule // texture_address$word$0


module texture_address$word$1(i,j,bank,first,pw,pwh,addr);
    
    // Module arguments
    input wire  [12:0] i;
    input wire  [12:0] j;
    input wire  [1:0] bank;
    input wire  [25:0] first;
    input wire  [3:0] pw;
    input wire  [4:0] pwh;
    output reg  [25:0] addr;
    
    // Local signals
    reg  [25:0] field;
    
    // Update code
    always @(*) begin
        field = (((bank) & 26'h3ffffff) << ((pwh) & 26'h3ffffff)) | (((j >> 32'h1) & 26'h3ffffff) << ((pw) & 26'h3ffffff)) | ((i >> 32'h1) & 26'h3ffffff);
        addr = first + field;
    end
    
endmodule // texture_address$word$1


module texture_address$word$2(i,j,bank,first,pw,pwh,addr);
    
    // Module arguments
    input wire  [12:0] i;
    input wire  [12:0] j;
    input wire  [1:0] bank;
    input wire  [25:0] first;
    input wire  [3:0] pw;
    input wire  [4:0] pwh;
    output reg  [25:0] addr;
    
    // Local signals
    reg  [25:0] field;
    
    // Update code
    always @(*) begin
        field = (((bank) & 26'h3ffffff) << ((pwh) & 26'h3ffffff)) | (((j >> 32'h1) & 26'h3ffffff) << ((pw) & 26'h3ffffff)) | ((i >> 32'h1) & 26'h3ffffff);
        addr = first + field;
    end
    
endmodule // texture_address$word$2


module texture_address$word$3(i,j,bank,first,pw,pwh,addr);
    
    // Module arguments
    input wire  [12:0] i;
    input wire  [12:0] j;
    input wire  [1:0] bank;
    input wire  [25:0] first;
    input wire  [3:0] pw;
    input wire  [4:0] pwh;
    output reg  [25:0] addr;
    
    // Local signals
    reg  [25:0] field;
    
    // Update code
    always @(*) begin
        field = (((bank) & 26'h3ffffff) << ((pwh) & 26'h3ffffff)) | (((j >> 32'h1) & 26'h3ffffff) << ((pw) & 26'h3ffffff)) | ((i >> 32'h1) & 26'h3ffffff);
        addr = first + field;
    end
    
endmodule // texture_address$word$3


module texture_address$wrap$0(i,size_log2,mode,wrapped);
    
    // Module arguments
    input wire  [21:0] i;
    input wire  [3:0] size_log2;
    input wire  [1:0] mode;
    output reg  [12:0] wrapped;
    
    // Local signals
    reg  [21:0] n;
    reg  [21:0] mask;
    reg  [21:0] low;
    reg  [21:0] high;
    
    // Update code
    always @(*) begin
        n = ((32'h1) & 22'h3fffff) << ((size_log2) & 22'h3fffff);
        mask = ~(((32'h3fffff) & 22'h3fffff) << ((size_log2) & 22'h3fffff));
        low = i & mask;
        high = i & ~mask;
        wrapped = ((low) & 13'h1fff);
        if ((mode == 32'h1) & |(i & n)) begin
            wrapped = ((~i & mask) & 13'h1fff);
        end
        if (mode == 32'h2) begin
            if (i[32'h15]) begin
                wrapped = 32'h0;
            end
            else if (|high) begin
                wrapped = ((mask) & 13'h1fff);
            end
        end
    end
    
endmodule // texture_address$wrap$0


module texture_address$wrap$1(i,size_log2,mode,wrapped);
    
    // Module arguments
    input wire  [21:0] i;
    input wire  [3:0] size_log2;
    input wire  [1:0] mode;
    output reg  [12:0] wrapped;
    
    // Local signals
    reg  [21:0] n;
    reg  [21:0] mask;
    reg  [21:0] low;
    reg  [21:0] high;
    
    // Update code
    always @(*) begin
        n = ((32'h1) & 22'h3fffff) << ((size_log2) & 22'h3fffff);
        mask = ~(((32'h3fffff) & 22'h3fffff) << ((size_log2) & 22'h3fffff));
        low = i & mask;
        high = i & ~mask;
        wrapped = ((low) & 13'h1fff);
        if ((mode == 32'h1) & |(i & n)) begin
            wrapped = ((~i & mask) & 13'h1fff);
        end
        if (mode == 32'h2) begin
            if (i[32'h15]) begin
                wrapped = 32'h0;
            end
            else if (|high) begin
                wrapped = ((mask) & 13'h1fff);
            end
        end
    end
    
endmodule // texture_address$wrap$1


module texture_address$wrap$2(i,size_log2,mode,wrapped);
    
    // Module arguments
    input wire  [21:0] i;
    input wire  [3:0] size_log2;
    input wire  [1:0] mode;
    output reg  [12:0] wrapped;
    
    // Local signals
    reg  [21:0] n;
    reg  [21:0] mask;
    reg  [21:0] low;
    reg  [21:0] high;
    
    // Update code
    always @(*) begin
        n = ((32'h1) & 22'h3fffff) << ((size_log2) & 22'h3fffff);
        mask = ~(((32'h3fffff) & 22'h3fffff) << ((size_log2) & 22'h3fffff));
        low = i & mask;
        high = i & ~mask;
        wrapped = ((low) & 13'h1fff);
        if ((mode == 32'h1) & |(i & n)) begin
            wrapped = ((~i & mask) & 13'h1fff);
        end
        if (mode == 32'h2) begin
            if (i[32'h15]) begin
                wrapped = 32'h0;
            end
            else if (|high) begin
                wrapped = ((mask) & 13'h1fff);
            end
        end
    end
    
endmodule // texture_address$wrap$2


module texture_address$wrap$3(i,size_log2,mode,wrapped);
    
    // Module arguments
    input wire  [21:0] i;
    input wire  [3:0] size_log2;
    input wire  [1:0] mode;
    output reg  [12:0] wrapped;
    
    // Local signals
    reg  [21:0] n;
    reg  [21:0] mask;
    reg  [21:0] low;
    reg  [21:0] high;
    
    // Update code
    always @(*) begin
        n = ((32'h1) & 22'h3fffff) << ((size_log2) & 22'h3fffff);
        mask = ~(((32'h3fffff) & 22'h3fffff) << ((size_log2) & 22'h3fffff));
        low = i & mask;
        high = i & ~mask;
        wrapped = ((low) & 13'h1fff);
        if ((mode == 32'h1) & |(i & n)) begin
            wrapped = ((~i & mask) & 13'h1fff);
        end
        if (mode == 32'h2) begin
            if (i[32'h15]) begin
                wrapped = 32'h0;
            end
            else if (|high) begin
                wrapped = ((mask) & 13'h1fff);
            end
        end
    end
    
endmodule // texture_address$wrap$3
